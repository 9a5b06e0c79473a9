// Three real lastcutd nodes on one PostgreSQL job ledger and one MQTT broker, both started by the
// test on 127.0.0.1 (issue #15, docs/multi-station.md): station-a and station-b compute and each
// own a simulated cutter on a pty (cutter-a an HPGL plotter, cutter-b a grbl table), compute-c only
// computes. 60 distinct scans, some dropped on both stations, go through in three waves while the
// test SIGKILLs compute-c mid-flatten, SIGKILLs station-a mid-cut and restarts it, restarts
// PostgreSQL (wave 2 is dropped while it is down) and restarts the broker.
// The independent truths: the ledger's own rows (jobs, batches, leases, job_events) read over the
// test's connection, the bytes each simulated cutter recorded against the batches' cut files in
// the shared folder, the SHA-256 of every dropped file by sha256sum, and what a fresh MQTT
// subscriber is told.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "tests/daemon/daemon_rig.hpp"
#include "tests/ledger/ledger_shop.hpp"

namespace lastcut::daemon::testing {
namespace {

using lastcut::test::MqttSubscriber;

constexpr int kScans = 60;
const std::vector<std::string> kNodes = {"station-a", "station-b", "compute-c"};

struct Scan {
  std::string name;
  std::string cutter;
  std::string sidecar;             // "" for none: the default cutter (cutter-a)
  std::vector<std::string> nodes;  // watch folders it is dropped into (two: the same bytes on both stations)
  int wave = 1;                    // 1 at the start, 2 while PostgreSQL is down, 3 after station-a's restart
};

// Scan i: even ones name cutter-b in their sidecar, i % 4 == 1 name cutter-a, i % 4 == 3 have no
// sidecar (the default, cutter-a); every other pair goes to the other station; 11 are dropped on both.
std::vector<Scan> plan() {
  std::vector<Scan> scans;
  for (int i = 0; i < kScans; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "scan-%02d.stl", i);
    Scan scan{name, i % 2 == 0 ? "cutter-b" : "cutter-a", "", {}, i < 36 ? 1 : i < 48 ? 2 : 3};
    if (i % 4 != 3) scan.sidecar = "cutter = \"" + scan.cutter + "\"\norder = \"O-" + std::to_string(i) + "\"\n";
    // Wave 2 is dropped while station-a is down: on station-b (the duplicates on both).
    const std::string home = scan.wave == 2 || (i / 2) % 2 == 1 ? "station-b" : "station-a";
    scan.nodes = {home};
    if (i % 10 == 5 || i % 12 == 6) scan.nodes.push_back(home == "station-a" ? "station-b" : "station-a");
    scans.push_back(scan);
  }
  return scans;
}

// Distinct bytes per scan (the STL header), three geometries.
void make_scans(const std::vector<Scan>& scans, const std::filesystem::path& staging) {
  const std::vector<std::filesystem::path> lasts = {small_last(40, "left", 1), small_last(41, "right", 2),
                                                    small_last(39, "left", 3)};
  std::filesystem::create_directories(staging);
  for (std::size_t i = 0; i < scans.size(); ++i) write_variant(lasts[i % 3], staging / scans[i].name, scans[i].name);
}

int drop_wave(LedgerShop& shop, const std::vector<Scan>& scans, const std::filesystem::path& staging, int wave) {
  int files = 0;
  for (const Scan& scan : scans) {
    if (scan.wave != wave) continue;
    const std::string stem = std::filesystem::path(scan.name).stem().string();
    if (!scan.sidecar.empty()) write_text(staging / (stem + ".job.toml"), scan.sidecar);
    for (const std::string& node : scan.nodes) {
      if (!scan.sidecar.empty()) drop(staging / (stem + ".job.toml"), shop.watch(node), stem + ".job.toml");
      drop(staging / scan.name, shop.watch(node), scan.name);
      ++files;
    }
  }
  return files;
}

// Files whose name holds ".stl" in a folder (scans, not sidecars or reasons).
int count_scans_in(const std::filesystem::path& folder) {
  int count = 0;
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name[0] != '.' && name.find(".stl") != std::string::npos) ++count;
  }
  return count;
}

// sha256sum over the staged scans: name -> hash (an implementation other than the daemon's).
std::map<std::string, std::string> sha256_of(const std::vector<Scan>& scans, const std::filesystem::path& staging) {
  std::vector<std::string> argv = {"/usr/bin/sha256sum"};
  for (const Scan& scan : scans) argv.push_back((staging / scan.name).string());
  const auto out = staging / "sha256.txt";
  std::filesystem::remove(out);
  EXPECT_EQ(run_command(argv, out), 0);
  std::map<std::string, std::string> hashes;
  std::istringstream lines(read_text(out));
  for (std::string hash, path; lines >> hash >> path;) hashes[std::filesystem::path(path).filename().string()] = hash;
  return hashes;
}

std::string id_list(const std::vector<std::string>& ids) {
  std::string out;
  for (const std::string& id : ids) out += (out.empty() ? "" : ",") + id;
  return out;
}

std::vector<std::string> column(const std::vector<std::vector<std::string>>& rows, std::size_t i = 0) {
  std::vector<std::string> out;
  for (const auto& row : rows) out.push_back(row.at(i));
  return out;
}

double now_epoch_s() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

std::string payload_of(const MqttSubscriber& subscriber, const std::string& topic) {
  const auto message = subscriber.last(topic);
  return message ? message->payload : "<none>";
}

TEST(LedgerMultiNode, SixtyScansOnThreeNodesEachCutOnceThroughKillsAndRestarts) {
  ShopOptions options;
  options.nodes = {{"station-a", {"compute", "station"}}, {"station-b", {"compute", "station"}}, {"compute-c", {"compute"}}};
  options.cutters = {{"cutter-a", "hpgl", "station-a"}, {"cutter-b", "grbl", "station-b"}};
  LedgerShop shop("ledger-multi-node", options);
  const auto staging = shop.root() / "staging";
  const std::vector<Scan> scans = plan();
  make_scans(scans, staging);
  ASSERT_EQ(shop.start_services(), "");
  MqttSubscriber watcher(shop.broker().port());
  ASSERT_TRUE(watcher.wait_subscribed(10));
  // cutter-a hangs at line 20 of the first batch it gets: station-a is killed while sending it.
  ASSERT_EQ(shop.start_cutter("cutter-a", "stall-at-line=20"), "");
  ASSERT_EQ(shop.start_cutter("cutter-b"), "");
  for (const std::string& node : kNodes) ASSERT_EQ(shop.start_node(node), "");
  const auto jobs_in = [&](const std::string& where) { return shop.count("SELECT count(*) FROM jobs " + where); };

  // Wave 1: 36 scans (6 of them dropped on both stations) become 36 jobs.
  int dropped = drop_wave(shop, scans, staging, 1);
  ASSERT_TRUE(wait_until([&] {
    return jobs_in("") == 36 && count_scans_in(shop.watch("station-a")) + count_scans_in(shop.watch("station-b")) == 0;
  }, 60)) << jobs_in("") << " jobs" << shop.log_tails();

  // compute-c killed while it flattens: its jobs are frozen in `computing` under its lease.
  const std::string computing_by_c =
      "SELECT l.object_id FROM leases l JOIN jobs j ON j.id = l.object_id WHERE l.kind = 'job' "
      "AND l.holder = 'compute-c' AND j.state = 'computing' ORDER BY 1";
  std::vector<std::string> orphans;
  double killed_at_s = 0;
  for (int attempt = 0; attempt < 3 && orphans.empty(); ++attempt) {
    ASSERT_TRUE(wait_until([&] { return !shop.value(computing_by_c).empty(); }, 60)) << shop.log_tails();
    shop.kill_node("compute-c");
    killed_at_s = now_epoch_s();
    orphans = column(shop.rows(computing_by_c));
    if (orphans.empty()) {
      ASSERT_EQ(shop.start_node("compute-c"), "");  // it had just finished: again
    }
  }
  // Frozen now that compute-c is dead: when each of its leases runs out, by the database's clock.
  std::map<std::string, double> expires_at_s;
  for (const std::string& job : orphans) {
    expires_at_s[job] = std::stod(shop.value("SELECT extract(epoch FROM expires_at) FROM leases WHERE kind = 'job' "
                                             "AND object_id = " + job));
  }
  ASSERT_FALSE(orphans.empty()) << "compute-c never killed while computing";
  const std::string orphan_ids = id_list(orphans);
  ASSERT_TRUE(wait_until([&] {
    return shop.count("SELECT count(*) FROM job_events WHERE event = 'computed' AND job_id IN (" + orphan_ids + ")") ==
           static_cast<long long>(orphans.size());
  }, 90)) << "jobs " << orphan_ids << shop.log_tails();
  for (const std::string& job : orphans) {
    // Handed back by another node's sweep, not before the lease ran out, then computed elsewhere.
    const auto requeued = shop.rows("SELECT node, extract(epoch FROM at) FROM job_events WHERE job_id = " + job +
                                    " AND event = 'requeued' ORDER BY id");
    ASSERT_EQ(requeued.size(), 1u) << "job " << job;
    EXPECT_NE(requeued[0][0], "compute-c");
    EXPECT_GE(std::stod(requeued[0][1]), expires_at_s[job]) << "job " << job << " handed back before its lease ran out";
    EXPECT_GT(expires_at_s[job], killed_at_s) << "compute-c's lease of job " << job << " was alive when it was killed";
    EXPECT_NE(shop.value("SELECT node FROM job_events WHERE job_id = " + job + " AND event = 'computed'"), "compute-c");
    EXPECT_GE(std::stoll(shop.value("SELECT epoch FROM leases WHERE kind = 'job' AND object_id = " + job)), 2);
  }
  ASSERT_EQ(shop.start_node("compute-c"), "");

  // station-a killed while its first batch is `sending` (the plotter hangs): held, never re-sent.
  std::string held_batch;
  ASSERT_TRUE(wait_until([&] {
    held_batch = shop.value("SELECT id FROM batches WHERE cutter = 'cutter-a' AND state = 'sending'");
    return !held_batch.empty();
  }, 120)) << shop.log_tails();
  shop.kill_node("station-a");
  EXPECT_EQ(shop.value("SELECT state FROM batches WHERE id = " + held_batch), "sending");
  EXPECT_TRUE(watcher.wait_until([&] { return payload_of(watcher, "lastcut/station/station-a/online") == "false"; }, 10))
      << "the broker's last will for station-a";
  ASSERT_TRUE(wait_until([&] { return shop.value("SELECT state FROM batches WHERE id = " + held_batch) == "held"; }, 30))
      << shop.log_tails();
  EXPECT_EQ(shop.count("SELECT count(*) FROM jobs WHERE batch_id = " + held_batch + " AND state <> 'held'"), 0);
  ASSERT_EQ(shop.start_cutter("cutter-a"), "");  // the plotter switched off and on: no fault now

  // PostgreSQL restarted once nothing is on its way to a cutter (cutter-b has cut wave 1, station-a
  // is down); wave 2 is dropped on station-b meanwhile: it stays in the watch folder until the
  // ledger is back, then enters.
  ASSERT_TRUE(wait_until([&] {
    return jobs_in("WHERE cutter = 'cutter-b' AND state = 'done'") == 18 &&
           shop.count("SELECT count(*) FROM batches WHERE cutter = 'cutter-b' AND state NOT IN ('cut', 'held')") == 0;
  }, 150)) << shop.log_tails();
  // Each of them was told over MQTT as it was cut, by the station that cut it (the watcher was
  // connected all along until here).
  for (const Scan& scan : scans) {
    if (scan.wave != 1 || scan.cutter != "cutter-b") continue;
    int cut_events = 0;
    for (const auto& message : watcher.messages()) {
      if (message.topic.rfind("lastcut/job/", 0) != 0) continue;
      const auto event = nlohmann::json::parse(message.payload, nullptr, false);
      if (event.is_object() && event.value("stage", "") == "cut" && event.value("scan", "") == scan.name) {
        ++cut_events;
        EXPECT_EQ(message.topic, "lastcut/job/" + event.value("job", "") + "/event");
        EXPECT_EQ(event.value("station", ""), "station-b") << scan.name;
        EXPECT_EQ(event.value("cutter", ""), "cutter-b") << scan.name;
      }
    }
    EXPECT_GE(cut_events, 1) << "no MQTT event for the cut of " << scan.name;  // QoS 1: at least once
  }
  ASSERT_EQ(shop.postgres().stop(), "");
  dropped += drop_wave(shop, scans, staging, 2);
  std::this_thread::sleep_for(std::chrono::seconds(2));
  EXPECT_EQ(count_scans_in(shop.watch("station-b")), 12) << "kept while the ledger is unreachable";
  EXPECT_EQ(count_scans_in(shop.spool("station-b") / "failed"), 0);
  ASSERT_EQ(shop.postgres().start(), "");
  ASSERT_TRUE(wait_until([&] { return jobs_in("") == 48 && count_scans_in(shop.watch("station-b")) == 0; }, 60))
      << jobs_in("") << " jobs" << shop.log_tails();

  // station-a back under the same name: carries on with its cutter's other batches.
  ASSERT_EQ(shop.start_node("station-a"), "");
  EXPECT_TRUE(watcher.wait_until([&] { return payload_of(watcher, "lastcut/station/station-a/online") == "true"; }, 15));
  dropped += drop_wave(shop, scans, staging, 3);

  // The broker restarted (it keeps nothing): the retained status comes back from every node.
  shop.broker().stop();
  std::this_thread::sleep_for(std::chrono::seconds(1));
  ASSERT_EQ(shop.broker().start(), "");
  {
    MqttSubscriber late(shop.broker().port());
    ASSERT_TRUE(late.wait_subscribed(10));
    const auto retained = [&](const std::string& topic) {
      const auto message = late.last(topic);
      return message && message->retained;
    };
    EXPECT_TRUE(late.wait_until([&] {
      for (const std::string& node : kNodes)
        if (payload_of(late, "lastcut/station/" + node + "/online") != "true" || !retained("lastcut/station/" + node + "/online"))
          return false;
      return retained("lastcut/cutter/cutter-a/state") && retained("lastcut/cutter/cutter-b/state");
    }, 30)) << "retained topics after the broker's restart";
    for (const auto& [cutter, station] : {std::pair{"cutter-a", "station-a"}, std::pair{"cutter-b", "station-b"}}) {
      const auto state = nlohmann::json::parse(payload_of(late, std::string("lastcut/cutter/") + cutter + "/state"), nullptr, false);
      EXPECT_EQ(state.is_object() ? state.value("station", "") : "", station) << cutter;
    }
  }

  // Everything settles: 60 jobs, each done or held, every batch cut or held, the watch folders empty.
  ASSERT_TRUE(wait_until([&] {
    return jobs_in("") == kScans && jobs_in("WHERE state NOT IN ('done', 'held')") == 0 &&
           shop.count("SELECT count(*) FROM batches WHERE state NOT IN ('cut', 'held')") == 0 &&
           count_scans_in(shop.watch("station-a")) + count_scans_in(shop.watch("station-b")) == 0;
  }, 180)) << jobs_in("WHERE state NOT IN ('done', 'held')") << " jobs unfinished" << shop.log_tails();
  for (const std::string& node : kNodes) EXPECT_EQ(shop.stop_node(node), 0) << node << shop.log_tails();
  shop.stop_cutter("cutter-a");
  shop.stop_cutter("cutter-b");

  // One job per distinct scan, under its SHA-256 (sha256sum's), its bytes in the shared folder;
  // every dropped file entered (duplicates too), none failed.
  const auto hashes = sha256_of(scans, staging);
  std::map<std::string, std::string> cutter_of;  // job id -> cutter
  std::map<std::string, std::string> state_of, batch_of;
  for (const auto& row : shop.rows("SELECT id, scan_sha256, scan_name, cutter, state, coalesce(batch_id, 0) FROM jobs")) {
    cutter_of[row[0]] = row[3];
    state_of[row[0]] = row[4];
    batch_of[row[0]] = row[5];
    const auto scan = std::find_if(scans.begin(), scans.end(), [&](const Scan& s) { return s.name == row[2]; });
    ASSERT_NE(scan, scans.end()) << row[2];
    EXPECT_EQ(row[1], hashes.at(scan->name)) << scan->name;
    EXPECT_EQ(row[3], scan->cutter) << scan->name;
    EXPECT_EQ(read_text(shop.shared_dir() / "scans" / (row[1] + ".stl")), read_text(staging / scan->name)) << scan->name;
  }
  EXPECT_EQ(cutter_of.size(), static_cast<std::size_t>(kScans));
  EXPECT_EQ(dropped, kScans + 11);
  EXPECT_EQ(count_scans_in(shop.spool("station-a") / "entered") + count_scans_in(shop.spool("station-b") / "entered"),
            dropped);
  for (const std::string& node : kNodes) EXPECT_EQ(count_scans_in(shop.spool(node) / "failed"), 0) << node;
  EXPECT_EQ(shop.count("SELECT count(*) FROM job_events WHERE event = 'entered'"), kScans);
  EXPECT_EQ(shop.count("SELECT count(*) FROM job_events WHERE event = 'duplicate'"), dropped - kScans);

  // Each job computed once and sent once; cut once unless it is in the held batch.
  const auto events = shop.rows("SELECT job_id, sum((event = 'computed')::int), sum((event = 'sending')::int), "
                                "sum((event = 'cut')::int) FROM job_events GROUP BY job_id");
  EXPECT_EQ(events.size(), static_cast<std::size_t>(kScans));
  for (const auto& row : events) {
    const bool held = batch_of[row[0]] == held_batch;
    EXPECT_EQ(state_of[row[0]], held ? "held" : "done") << "job " << row[0];
    EXPECT_EQ(row[1], "1") << "computed, job " << row[0];
    EXPECT_EQ(row[2], "1") << "sending, job " << row[0];
    EXPECT_EQ(row[3], held ? "0" : "1") << "cut, job " << row[0];
  }

  // Every batch's cut file reached its own cutter exactly once and nothing else did; the held
  // batch reached cutter-a at most in part (the hang), and never after the restart.
  const std::vector<std::string> runs_a = shop.received_per_run("cutter-a");
  ASSERT_EQ(runs_a.size(), 2u);
  const std::string received_b = shop.received("cutter-b");
  std::map<std::string, std::size_t> bytes_cut;
  std::string held_cut;
  for (const auto& row : shop.rows("SELECT id, cutter, state, coalesce(cut_file, '') FROM batches ORDER BY id")) {
    const std::string& id = row[0];
    const std::string& cutter = row[1];
    const std::string name = cutter == "cutter-b" ? "cut.nc" : "cut.plt";
    EXPECT_EQ(std::filesystem::path(row[3]).filename().string(), name) << "batch " << id;
    const std::string cut = read_text(shop.shared_dir() / "batches" / id / name);
    ASSERT_FALSE(cut.empty()) << "batch " << id;
    const std::string& own = cutter == "cutter-b" ? received_b : runs_a[1];
    const std::string& other = cutter == "cutter-b" ? runs_a[1] : received_b;
    EXPECT_EQ(count_occurrences(other, cut), 0) << "batch " << id;
    if (id == held_batch) {
      EXPECT_EQ(row[2], "held");
      EXPECT_EQ(count_occurrences(own, cut), 0) << "the held batch was sent again";
      held_cut = cut;
      continue;
    }
    EXPECT_EQ(row[2], "cut") << "batch " << id;
    EXPECT_EQ(count_occurrences(own, cut), 1) << "batch " << id;
    bytes_cut[cutter] += cut.size();
    for (const auto& [job, batch] : batch_of) {
      if (batch == id) {
        EXPECT_EQ(cutter_of[job], cutter) << "job " << job << " in batch " << id;
      }
    }
  }
  EXPECT_EQ(received_b.size(), bytes_cut["cutter-b"]) << "cutter-b got more than its batches";
  EXPECT_EQ(runs_a[1].size(), bytes_cut["cutter-a"]) << "cutter-a got more than its batches after the restart";
  ASSERT_FALSE(held_cut.empty());
  EXPECT_LT(runs_a[0].size(), held_cut.size());
  EXPECT_EQ(held_cut.compare(0, runs_a[0].size(), runs_a[0]), 0) << "before the kill cutter-a got a part of the held batch only";
}

}  // namespace
}  // namespace lastcut::daemon::testing
