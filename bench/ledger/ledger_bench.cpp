// bench_ledger: N nodes x M scans through the PostgreSQL job ledger, each node a thread with its
// own connection doing what a lastcutd node does per scan: enter it (drop), claim the oldest
// ready job, mark it computed, group computed jobs into batches, and, as the station owning one
// cutter, claim a batch, mark it sending and cut. Nothing is computed or cut: this measures the
// ledger alone. Prints claims per second, the time from a scan's entry to its claim (p50/p99),
// and the ledger's rows and bytes per finished job.
//
//   bench_ledger [--nodes 3] [--scans 200]
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>
#include <thread>

#include <CLI/CLI.hpp>
#include <pqxx/pqxx>

#include "daemon/ledger/ledger_client.hpp"
#include "daemon/ledger_node/ledger_batch_rule.hpp"
#include "tests/support/postgres_server.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using lastcut::Status;
using lastcut::ledger::LedgerClient;

struct Shared {
  std::mutex mutex;
  std::map<long long, Clock::time_point> entered;  // job id -> when its enqueue committed
  std::vector<double> drop_to_claim_ms;
  std::atomic<long long> claims{0}, cut_batches{0};
  std::string failure;

  void fail(const std::string& why) {
    std::lock_guard lock(mutex);
    if (failure.empty()) failure = why;
  }
};

std::string hash_of(int node, int scan) {
  char hex[65];
  std::snprintf(hex, sizeof(hex), "%032x%032x", node + 1, scan + 1);
  return hex;
}

// A compute node's part of a batch, nothing nested: group computed jobs (no window), hand the
// batch to its station.
lastcut::Status make_nested_batch(LedgerClient& client) {
  lastcut::daemon::BatchConfig rule;
  rule.max_pieces = 5;  // every job here has 1 piece: batches of 5 jobs, as bench_spool's
  auto made = client.make_batch(lastcut::daemon::ledger_batch_rule(rule), 30);
  if (!made) return made.status();
  if (!made->has_value()) return lastcut::Status::success();
  return client.mark_nested((*made)->lease, {"batches/" + std::to_string((*made)->batch_id) + "/cut.nc", 1, {}});
}

void run_node(const std::string& url, int node, int nodes, int scans, Shared& shared) {
  auto connected = LedgerClient::connect(url, "node-" + std::to_string(node));
  if (!connected) return shared.fail(connected.error());
  LedgerClient& client = **connected;
  const std::string cutter = "cutter-" + std::to_string(node);
  if (auto registered = client.register_node({"compute", "station"}, {cutter}, 3); !registered) {
    return shared.fail(registered.error());
  }
  int dropped = 0;
  // Until every node's scans are cut: the last batches may belong to another node's cutter.
  for (;;) {
    if (dropped < scans) {
      const std::string target = "cutter-" + std::to_string((node + dropped) % nodes);
      auto entered = client.enqueue({hash_of(node, dropped), "scan.stl", "", "calf", target});
      if (!entered) return shared.fail(entered.error());
      std::lock_guard lock(shared.mutex);
      shared.entered[entered->job_id] = Clock::now();
      ++dropped;
    }
    auto claim = client.claim_job(30);
    if (!claim) return shared.fail(claim.error());
    if (claim->has_value()) {
      const auto now = Clock::now();
      {
        std::lock_guard lock(shared.mutex);
        const auto at = shared.entered.find((*claim)->job_id);
        if (at != shared.entered.end()) {
          shared.drop_to_claim_ms.push_back(std::chrono::duration<double, std::milli>(now - at->second).count());
        }
      }
      ++shared.claims;
      if (Status done = client.mark_computed((*claim)->lease); !done) return shared.fail(done.error());
      if (Status made = make_nested_batch(client); !made) return shared.fail(made.error());
    }
    auto batch = client.claim_batch(30);
    if (!batch) return shared.fail(batch.error());
    if (batch->has_value()) {
      if (Status s = client.mark_sending((*batch)->lease); !s) return shared.fail(s.error());
      if (Status s = client.mark_cut((*batch)->lease); !s) return shared.fail(s.error());
      ++shared.cut_batches;
    }
    if (dropped == scans && !claim->has_value() && !batch->has_value()) {
      // Nothing for this node now: finished when no job anywhere is short of done.
      // A last partial group.
      if (Status made = make_nested_batch(client); !made) return shared.fail(made.error());
      pqxx::connection look(url);
      pqxx::read_transaction tx(look);
      if (tx.exec("SELECT count(*) FROM jobs WHERE state <> 'done'")[0][0].as<long long>() == 0) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<std::size_t>(p * (values.size() - 1) + 0.5))];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench_ledger: the PostgreSQL job ledger under N nodes x M scans"};
  int nodes = 3, scans = 200;
  app.add_option("--nodes", nodes, "nodes (threads, one connection each)")->check(CLI::Range(1, 50));
  app.add_option("--scans", scans, "scans dropped per node")->check(CLI::Range(1, 100000));
  CLI11_PARSE(app, argc, argv);

  lastcut::test::PostgresServer server(/*durable=*/true);
  if (std::string failed = server.start(); !failed.empty()) {
    std::fprintf(stderr, "bench_ledger: %s\n", failed.c_str());
    return 1;
  }
  std::string error;
  const std::string url = server.create_database("lastcut", error);
  if (url.empty()) {
    std::fprintf(stderr, "bench_ledger: %s\n", error.c_str());
    return 1;
  }
  {
    auto client = LedgerClient::connect(url, "setup");
    if (!client || !(*client)->migrate()) {
      std::fprintf(stderr, "bench_ledger: cannot prepare the ledger\n");
      return 1;
    }
  }
  Shared shared;
  const auto start = Clock::now();
  std::vector<std::thread> threads;
  for (int node = 0; node < nodes; ++node) {
    threads.emplace_back(run_node, url, node, nodes, scans, std::ref(shared));
  }
  for (auto& thread : threads) thread.join();
  const double wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  if (!shared.failure.empty()) {
    std::fprintf(stderr, "bench_ledger: %s\n", shared.failure.c_str());
    return 1;
  }

  pqxx::connection look(url);
  pqxx::read_transaction tx(look);
  const long long jobs = tx.exec("SELECT count(*) FROM jobs WHERE state = 'done'")[0][0].as<long long>();
  const long long twice = tx.exec("SELECT count(*) FROM jobs WHERE attempts <> 1")[0][0].as<long long>();
  long long rows = 0, bytes = 0;
  std::printf("| table | rows | bytes (with indexes) |\n|---|---|---|\n");
  for (const char* table : {"jobs", "job_events", "batches", "leases", "nodes", "cutters"}) {
    const long long n = tx.exec(std::string("SELECT count(*) FROM ") + table)[0][0].as<long long>();
    const long long b =
        tx.exec(std::string("SELECT pg_total_relation_size('") + table + "')")[0][0].as<long long>();
    rows += n;
    bytes += b;
    std::printf("| %s | %lld | %lld |\n", table, n, b);
  }
  std::printf("\nnodes %d, scans %d per node, jobs done %lld of %d (claimed more than once: %lld), wall %.2f s\n",
              nodes, scans, jobs, nodes * scans, twice, wall_s);
  std::printf("claims per second: %.0f (each scan: enqueue, claim, computed, batch, sending, cut)\n",
              shared.claims.load() / wall_s);
  std::printf("drop to claim: p50 %.1f ms, p99 %.1f ms\n", percentile(shared.drop_to_claim_ms, 0.5),
              percentile(shared.drop_to_claim_ms, 0.99));
  std::printf("ledger per job: %.1f rows, %.0f bytes (tables and indexes, fsync on)\n",
              jobs ? double(rows) / jobs : 0.0, jobs ? double(bytes) / jobs : 0.0);
  return jobs == nodes * scans && twice == 0 ? 0 : 2;
}
