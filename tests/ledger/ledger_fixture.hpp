#pragma once
// A fresh PostgreSQL server and database per test, and ledger clients on it (migrated).
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include <pqxx/pqxx>

#include "daemon/ledger/ledger_client.hpp"
#include "daemon/ledger_node/ledger_batch_rule.hpp"
#include "tests/support/postgres_server.hpp"

namespace lastcut::test {

class LedgerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string failure = server_.start();
    ASSERT_TRUE(failure.empty()) << failure;
    std::string error;
    url_ = server_.create_database("lastcut", error);
    ASSERT_FALSE(url_.empty()) << error;
  }

  // A client of node `name` on the test's database, the schema migrated.
  std::unique_ptr<ledger::LedgerClient> client(const std::string& name) {
    auto connected = ledger::LedgerClient::connect(url_, name);
    EXPECT_TRUE(connected.ok()) << connected.error();
    if (!connected) return nullptr;
    auto migrated = (*connected)->migrate();
    EXPECT_TRUE(migrated.ok()) << migrated.error();
    return std::move(*connected);
  }

  // One value of a query, as text, read over a connection of its own (an independent look).
  std::string query(const std::string& sql) {
    pqxx::connection connection(url_);
    pqxx::read_transaction tx(connection);
    const pqxx::result r = tx.exec(sql);
    return r.empty() || r[0][0].is_null() ? "" : r[0][0].as<std::string>();
  }

  // The start of the lease tests: nodes node-a (holder) and node-b (other), scan 1 entered by node-a
  // and claimed by it with a lease of lease_s. Call inside ASSERT_NO_FATAL_FAILURE.
  struct HeldJob {
    std::unique_ptr<ledger::LedgerClient> holder, other;
    ledger::JobClaim claim;
  };
  void hold_one_job(double lease_s, HeldJob& held);

  // Waits until a lease of lease_s taken or renewed now has run out (twice its length: the database
  // decides by its own clock), then lets `sweeper` hand expired leases back: its outcome.
  static Result<ledger::SweepOutcome> sweep_after_expiry(ledger::LedgerClient& sweeper, double lease_s,
                                                         int max_attempts = 3) {
    std::this_thread::sleep_for(std::chrono::duration<double>(2 * lease_s));
    return sweeper.sweep_expired(max_attempts);
  }

  PostgresServer server_;
  std::string url_;
};

// A scan entry whose hash is derived from `n` (64 hex digits, distinct per n).
inline ledger::ScanEntry scan(int n, const std::string& cutter = "cutter-1", const std::string& material = "calf") {
  char hex[65];
  std::snprintf(hex, sizeof(hex), "%064x", n);
  return {hex, "scan-" + std::to_string(n) + ".stl", "", material, cutter};
}

// The station's batching rule with a window and a piece limit (every test job has 1 piece).
inline ledger::BatchChooser batch_rule(double window_s, int max_pieces, bool force = false) {
  daemon::BatchConfig rule;
  rule.window_s = window_s;
  rule.max_pieces = max_pieces;
  return daemon::ledger_batch_rule(rule, force);
}

// Groups the oldest computed jobs of one material and cutter at once, whatever they waited (the
// station's rule forced, as for a stopping station), up to max_pieces: for tests of the ledger's
// grouping itself. (A window of 0 would nest each job alone.)
inline ledger::BatchChooser group_now(int max_pieces) { return batch_rule(3600, max_pieces, true); }

// What a compute node does to a batch (nothing is really nested here): groups the oldest computed
// jobs (group_now) and hands the batch to its station with a cut file named after it. nullopt when
// nothing is computed; the failure of a ledger call fails the test.
inline std::optional<long long> nest_batch(ledger::LedgerClient& compute, int max_jobs) {
  auto made = compute.make_batch(group_now(max_jobs), 30);
  EXPECT_TRUE(made.ok()) << made.error();
  if (!made || !made->has_value()) return std::nullopt;
  const long long id = (*made)->batch_id;
  const Status nested =
      compute.mark_nested((*made)->lease, {"batches/" + std::to_string(id) + "/cut.nc", 1, {}});
  EXPECT_TRUE(nested.ok()) << nested.error();
  return id;
}

inline void LedgerTest::hold_one_job(double lease_s, HeldJob& held) {
  held.holder = client("node-a");
  held.other = client("node-b");
  ASSERT_TRUE(held.holder && held.other);
  ASSERT_TRUE(held.holder->enqueue(scan(1)).ok());
  auto claimed = held.holder->claim_job(lease_s);
  ASSERT_TRUE(claimed.ok() && claimed->has_value()) << claimed.error();
  held.claim = **claimed;
}

}  // namespace lastcut::test
