// Three real lastcutd nodes on one PostgreSQL job ledger and one MQTT broker, both started by the
// test on 127.0.0.1 (issue #15, docs/multi-station.md): station-a and station-b compute and each
// own a simulated cutter on a pty (cutter-a an HPGL plotter, cutter-b a grbl table), compute-c only
// computes. 60 distinct scans, 11 of them dropped on both stations, go through in three waves while
// the test SIGKILLs compute-c mid-flatten, SIGKILLs station-a mid-cut and restarts it, restarts
// PostgreSQL (wave 2 is dropped while it is down) and restarts the broker.
// The independent truths: the ledger's own rows (jobs, batches, leases, job_events) read over the
// test's connection, the bytes each simulated cutter recorded against the batches' cut files in
// the shared folder, the SHA-256 of every dropped file by sha256sum, and what MQTT subscribers hear.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include <nlohmann/json.hpp>

#include "tests/daemon/daemon_rig.hpp"
#include "tests/ledger/ledger_shop.hpp"
#include "tests/ledger/shop_scans.hpp"

namespace lastcut::daemon::testing {
namespace {

using lastcut::test::MqttSubscriber;

constexpr int kScans = 60;
const std::vector<std::string> kNodes = {"station-a", "station-b", "compute-c"};

ShopOptions shop_options() {
  ShopOptions options;
  options.nodes = {{"station-a", {"compute", "station"}}, {"station-b", {"compute", "station"}}, {"compute-c", {"compute"}}};
  options.cutters = {{"cutter-a", "hpgl", "station-a"}, {"cutter-b", "grbl", "station-b"}};
  return options;
}

std::string id_list(const std::vector<std::string>& ids) {
  std::string out;
  for (const std::string& id : ids) out += (out.empty() ? "" : ",") + id;
  return out;
}

double now_epoch_s() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

std::string payload_of(const MqttSubscriber& subscriber, const std::string& topic) {
  const auto message = subscriber.last(topic);
  return message ? message->payload : "<none>";
}

class LedgerMultiNode : public ::testing::Test {
 protected:
  LedgerMultiNode() : shop_("ledger-multi-node", shop_options()), staging_(shop_.root() / "staging"), scans_(plan_scans(kScans)) {}

  long long jobs_in(const std::string& where) const { return shop_.count("SELECT count(*) FROM jobs " + where); }
  int scans_waiting() const { return count_scans_in(shop_.watch("station-a")) + count_scans_in(shop_.watch("station-b")); }

  void start_shop();
  void kill_compute_mid_flatten();
  void kill_station_mid_cut();
  void restart_postgres_during_wave_2();
  void restart_station_and_broker();
  void check_jobs_and_events();
  void check_cut_bytes();

  LedgerShop shop_;
  std::filesystem::path staging_;
  std::vector<ShopScan> scans_;
  std::unique_ptr<MqttSubscriber> watcher_;  // connected from the start (through the broker's restart)
  int dropped_ = 0;                          // scan files dropped into watch folders
  std::string held_batch_;                   // the batch station-a was sending when killed
};

void LedgerMultiNode::start_shop() {
  make_scans(scans_, staging_);
  ASSERT_EQ(shop_.start_services(), "");
  watcher_ = std::make_unique<MqttSubscriber>(shop_.broker().port());
  ASSERT_TRUE(watcher_->wait_subscribed(10));
  // cutter-a hangs at line 20 of the first batch it gets: station-a is killed while sending it.
  ASSERT_EQ(shop_.start_cutter("cutter-a", "stall-at-line=20"), "");
  ASSERT_EQ(shop_.start_cutter("cutter-b"), "");
  for (const std::string& node : kNodes) ASSERT_EQ(shop_.start_node(node), "");
  // Wave 1: 36 scans (6 of them dropped on both stations) become 36 jobs.
  dropped_ += drop_wave(shop_, scans_, staging_, 1);
  ASSERT_TRUE(wait_until([&] { return jobs_in("") == 36 && scans_waiting() == 0; }, 60))
      << jobs_in("") << " jobs" << shop_.log_tails();
}

// compute-c killed while the leases table shows it holding a job in `computing`: each such job goes
// back to the queue by another node's sweep, not before its lease ran out, and is computed elsewhere.
void LedgerMultiNode::kill_compute_mid_flatten() {
  const std::string computing_by_c =
      "SELECT l.object_id FROM leases l JOIN jobs j ON j.id = l.object_id WHERE l.kind = 'job' "
      "AND l.holder = 'compute-c' AND j.state = 'computing' ORDER BY 1";
  std::vector<std::string> orphans;
  double killed_at_s = 0;
  for (int attempt = 0; attempt < 3 && orphans.empty(); ++attempt) {
    ASSERT_TRUE(wait_until([&] { return !shop_.value(computing_by_c).empty(); }, 60)) << shop_.log_tails();
    shop_.kill_node("compute-c");
    killed_at_s = now_epoch_s();
    for (const auto& row : shop_.rows(computing_by_c)) orphans.push_back(row[0]);
    if (orphans.empty()) {
      ASSERT_EQ(shop_.start_node("compute-c"), "");  // it had just finished: again
    }
  }
  ASSERT_FALSE(orphans.empty()) << "compute-c never killed while computing";
  // Frozen now that compute-c is dead: when each of its leases runs out, by the database's clock.
  std::map<std::string, double> expires_at_s;
  for (const std::string& job : orphans) {
    expires_at_s[job] = std::stod(
        shop_.value("SELECT extract(epoch FROM expires_at) FROM leases WHERE kind = 'job' AND object_id = " + job));
  }
  const std::string ids = id_list(orphans);
  ASSERT_TRUE(wait_until([&] {
    return shop_.count("SELECT count(*) FROM job_events WHERE event = 'computed' AND job_id IN (" + ids + ")") ==
           static_cast<long long>(orphans.size());
  }, 90)) << "jobs " << ids << shop_.log_tails();
  for (const std::string& job : orphans) {
    const auto requeued = shop_.rows("SELECT node, extract(epoch FROM at) FROM job_events WHERE job_id = " + job +
                                     " AND event = 'requeued' ORDER BY id");
    ASSERT_EQ(requeued.size(), 1u) << "job " << job;
    EXPECT_NE(requeued[0][0], "compute-c");
    EXPECT_GT(expires_at_s[job], killed_at_s) << "compute-c's lease of job " << job << " was alive when it was killed";
    EXPECT_GE(std::stod(requeued[0][1]), expires_at_s[job]) << "job " << job << " handed back before its lease ran out";
    EXPECT_NE(shop_.value("SELECT node FROM job_events WHERE job_id = " + job + " AND event = 'computed'"), "compute-c");
    EXPECT_GE(std::stoll(shop_.value("SELECT epoch FROM leases WHERE kind = 'job' AND object_id = " + job)), 2);
  }
  ASSERT_EQ(shop_.start_node("compute-c"), "");
}

// station-a killed while its first batch is `sending` (the plotter hangs): the broker tells its
// last will, the batch is held with its jobs; the plotter is switched off and on (no fault now).
void LedgerMultiNode::kill_station_mid_cut() {
  ASSERT_TRUE(wait_until([&] {
    held_batch_ = shop_.value("SELECT id FROM batches WHERE cutter = 'cutter-a' AND state = 'sending'");
    return !held_batch_.empty();
  }, 120)) << shop_.log_tails();
  shop_.kill_node("station-a");
  EXPECT_EQ(shop_.value("SELECT state FROM batches WHERE id = " + held_batch_), "sending");
  EXPECT_TRUE(watcher_->wait_until([&] { return payload_of(*watcher_, "lastcut/station/station-a/online") == "false"; }, 10))
      << "the broker's last will for station-a";
  ASSERT_TRUE(wait_until([&] { return shop_.value("SELECT state FROM batches WHERE id = " + held_batch_) == "held"; }, 30))
      << shop_.log_tails();
  EXPECT_EQ(jobs_in("WHERE batch_id = " + held_batch_ + " AND state <> 'held'"), 0);
  ASSERT_EQ(shop_.start_cutter("cutter-a"), "");
}

// PostgreSQL restarted once nothing is on its way to a cutter (cutter-b has cut wave 1, station-a is
// down). Wave 2 is dropped on station-b meanwhile: it stays in the watch folder until the ledger is
// back, then enters.
void LedgerMultiNode::restart_postgres_during_wave_2() {
  ASSERT_TRUE(wait_until([&] {
    return jobs_in("WHERE cutter = 'cutter-b' AND state = 'done'") == 18 &&
           shop_.count("SELECT count(*) FROM batches WHERE cutter = 'cutter-b' AND state NOT IN ('cut', 'held', 'dissolved')") == 0;
  }, 150)) << shop_.log_tails();
  // Each of these cuts was told over MQTT by station-b, on the topic of the ledger's job (the
  // watcher was connected all along).
  for (const auto& row : shop_.rows("SELECT id, scan_name FROM jobs WHERE cutter = 'cutter-b'")) {
    int cut_events = 0;
    for (const auto& message : watcher_->on("lastcut/job/" + row[0] + "/event")) {
      const auto event = nlohmann::json::parse(message.payload, nullptr, false);
      if (!event.is_object() || event.value("stage", "") != "cut") continue;
      ++cut_events;
      EXPECT_EQ(event.value("job", ""), row[0]) << row[1];
      EXPECT_EQ(event.value("station", ""), "station-b") << row[1];
    }
    EXPECT_GE(cut_events, 1) << "no MQTT event for the cut of job " << row[0] << " (" << row[1] << ")";  // QoS 1
  }
  ASSERT_EQ(shop_.postgres().stop(), "");
  dropped_ += drop_wave(shop_, scans_, staging_, 2);
  std::this_thread::sleep_for(std::chrono::seconds(2));
  EXPECT_EQ(count_scans_in(shop_.watch("station-b")), 12) << "kept while the ledger is unreachable";
  EXPECT_EQ(count_scans_in(shop_.spool("station-b") / "failed"), 0);
  ASSERT_EQ(shop_.postgres().start(), "");
  ASSERT_TRUE(wait_until([&] { return jobs_in("") == 48 && count_scans_in(shop_.watch("station-b")) == 0; }, 60))
      << jobs_in("") << " jobs" << shop_.log_tails();
}

// station-a back under the same name, wave 3 dropped, then the broker restarted (it keeps nothing):
// a subscriber arriving afterwards gets every node's retained status again.
void LedgerMultiNode::restart_station_and_broker() {
  ASSERT_EQ(shop_.start_node("station-a"), "");
  EXPECT_TRUE(watcher_->wait_until([&] { return payload_of(*watcher_, "lastcut/station/station-a/online") == "true"; }, 15));
  dropped_ += drop_wave(shop_, scans_, staging_, 3);
  shop_.broker().stop();
  std::this_thread::sleep_for(std::chrono::seconds(1));
  // Counted once the broker is gone: a cutter busy cutting publishes progress live until the stop,
  // and what reached the watcher before it must not pass for the nodes' publishing again.
  const std::size_t heard_before = watcher_->messages().size();
  ASSERT_EQ(shop_.broker().start(), "");
  // The nodes publish again once they are back (a subscriber already there gets that live, not
  // retained): wait for it on the watcher, then ask a new subscriber what the broker keeps.
  const auto heard_again = [&](const std::string& topic) {
    const auto heard = watcher_->messages();
    for (std::size_t i = heard_before; i < heard.size(); ++i)
      if (heard[i].topic == topic) return true;
    return false;
  };
  EXPECT_TRUE(watcher_->wait_until([&] {
    for (const std::string& node : kNodes)
      if (!heard_again("lastcut/station/" + node + "/online")) return false;
    return heard_again("lastcut/cutter/cutter-a/state") && heard_again("lastcut/cutter/cutter-b/state");
  }, 30)) << "status not published again after the broker's restart";
  MqttSubscriber late(shop_.broker().port());
  ASSERT_TRUE(late.wait_subscribed(10));
  // The broker hands a new subscriber the retained copy first; a cutter busy cutting may already
  // have published live progress after it, so the retained copy is looked for, not the last message.
  const auto retained = [&](const std::string& topic) {
    for (const lastcut::test::MqttMessage& message : late.on(topic))
      if (message.retained) return true;
    return false;
  };
  EXPECT_TRUE(late.wait_until([&] {
    for (const std::string& node : kNodes) {
      const std::string topic = "lastcut/station/" + node + "/online";
      if (payload_of(late, topic) != "true" || !retained(topic)) return false;
    }
    return retained("lastcut/cutter/cutter-a/state") && retained("lastcut/cutter/cutter-b/state");
  }, 10)) << "retained topics after the broker's restart: station-a " << payload_of(late, "lastcut/station/station-a/online")
          << ", station-b " << payload_of(late, "lastcut/station/station-b/online") << ", compute-c "
          << payload_of(late, "lastcut/station/compute-c/online") << ", cutter-a "
          << payload_of(late, "lastcut/cutter/cutter-a/state") << ", cutter-b " << payload_of(late, "lastcut/cutter/cutter-b/state");
  for (const auto& [cutter, station] : {std::pair{"cutter-a", "station-a"}, std::pair{"cutter-b", "station-b"}}) {
    const auto state = nlohmann::json::parse(payload_of(late, std::string("lastcut/cutter/") + cutter + "/state"), nullptr, false);
    EXPECT_EQ(state.is_object() ? state.value("station", "") : "", station) << cutter;
  }
}

// One job per distinct scan under its SHA-256, its bytes in the shared folder, on the cutter its
// sidecar named; every dropped file entered, none failed; each job computed once and sent once,
// cut once unless it is in the held batch.
void LedgerMultiNode::check_jobs_and_events() {
  const auto hashes = sha256_of(scans_, staging_);
  std::map<std::string, std::string> state_of, batch_of;
  for (const auto& row : shop_.rows("SELECT id, scan_sha256, scan_name, cutter, state, coalesce(batch_id, 0) FROM jobs")) {
    state_of[row[0]] = row[4];
    batch_of[row[0]] = row[5];
    const auto scan = std::find_if(scans_.begin(), scans_.end(), [&](const ShopScan& s) { return s.name == row[2]; });
    ASSERT_NE(scan, scans_.end()) << row[2];
    EXPECT_EQ(row[1], hashes.at(scan->name)) << scan->name;
    EXPECT_EQ(row[3], scan->cutter) << scan->name;
    EXPECT_EQ(read_text(shop_.shared_dir() / "scans" / (row[1] + ".stl")), read_text(staging_ / scan->name)) << scan->name;
  }
  EXPECT_EQ(state_of.size(), static_cast<std::size_t>(kScans));
  EXPECT_EQ(dropped_, kScans + 11);
  EXPECT_EQ(count_scans_in(shop_.spool("station-a") / "entered") + count_scans_in(shop_.spool("station-b") / "entered"),
            dropped_);
  for (const std::string& node : kNodes) EXPECT_EQ(count_scans_in(shop_.spool(node) / "failed"), 0) << node;
  EXPECT_EQ(shop_.count("SELECT count(*) FROM job_events WHERE event = 'entered'"), kScans);
  EXPECT_EQ(shop_.count("SELECT count(*) FROM job_events WHERE event = 'duplicate'"), dropped_ - kScans);

  // A batch the cutter refused before its first byte is "not sent" and queued again: sent is
  // sending minus those.
  const auto events = shop_.rows("SELECT job_id, sum((event = 'computed')::int), "
                                 "sum((event = 'sending')::int) - sum((event = 'not sent')::int), "
                                 "sum((event = 'cut')::int) FROM job_events GROUP BY job_id");
  EXPECT_EQ(events.size(), static_cast<std::size_t>(kScans));
  for (const auto& row : events) {
    const bool held = batch_of[row[0]] == held_batch_;
    EXPECT_EQ(state_of[row[0]], held ? "held" : "done") << "job " << row[0];
    EXPECT_EQ(row[1], "1") << "computed, job " << row[0];
    EXPECT_EQ(row[2], "1") << "sending, job " << row[0];
    EXPECT_EQ(row[3], held ? "0" : "1") << "cut, job " << row[0];
  }
  EXPECT_EQ(shop_.count("SELECT count(*) FROM jobs j JOIN batches b ON b.id = j.batch_id WHERE j.cutter <> b.cutter"), 0);
}

// Every cut batch's cut file reached its own cutter exactly once, never the other, and nothing else
// reached either; the held batch reached cutter-a only in part before the kill, never after it.
void LedgerMultiNode::check_cut_bytes() {
  const std::vector<std::string> runs_a = shop_.received_per_run("cutter-a");
  ASSERT_EQ(runs_a.size(), 2u);
  const std::string received_b = shop_.received("cutter-b");
  std::map<std::string, std::size_t> bytes_cut;
  std::string held_cut;
  for (const auto& row : shop_.rows("SELECT id, cutter, state, cut_file FROM batches ORDER BY id")) {
    const std::string &id = row[0], &cutter = row[1];
    const std::string name = "batches/" + id + (cutter == "cutter-b" ? "/cut.nc" : "/cut.plt");
    const std::string cut = read_text(shop_.shared_dir() / name);
    const std::string& own = cutter == "cutter-b" ? received_b : runs_a[1];
    if (row[2] == "dissolved") {
      // Its nesting node vanished: its jobs were regrouped, nothing of it may reach a cutter.
      EXPECT_EQ(jobs_in("WHERE batch_id = " + id), 0) << "batch " << id;
      EXPECT_EQ(row[3], "") << "batch " << id;
      if (!cut.empty()) {
        EXPECT_EQ(count_occurrences(own + runs_a[0], cut), 0) << "dissolved batch " << id;
      }
      continue;
    }
    EXPECT_EQ(row[3], name) << "batch " << id;
    ASSERT_FALSE(cut.empty()) << "batch " << id;
    EXPECT_EQ(count_occurrences(cutter == "cutter-b" ? runs_a[1] : received_b, cut), 0) << "batch " << id;
    if (id == held_batch_) {
      EXPECT_EQ(row[2], "held");
      EXPECT_EQ(count_occurrences(own, cut), 0) << "the held batch was sent again";
      held_cut = cut;
      continue;
    }
    EXPECT_EQ(row[2], "cut") << "batch " << id;
    EXPECT_EQ(count_occurrences(own, cut), 1) << "batch " << id;
    bytes_cut[cutter] += cut.size();
  }
  EXPECT_EQ(received_b.size(), bytes_cut["cutter-b"]) << "cutter-b received more than its batches";
  EXPECT_EQ(runs_a[1].size(), bytes_cut["cutter-a"]) << "cutter-a received more than its batches after the restart";
  ASSERT_FALSE(held_cut.empty());
  EXPECT_LT(runs_a[0].size(), held_cut.size());
  EXPECT_EQ(held_cut.compare(0, runs_a[0].size(), runs_a[0]), 0) << "before the kill cutter-a got part of the held batch only";
}

TEST_F(LedgerMultiNode, SixtyScansOnThreeNodesEachCutOnceThroughKillsAndRestarts) {
  ASSERT_NO_FATAL_FAILURE(start_shop());
  ASSERT_NO_FATAL_FAILURE(kill_compute_mid_flatten());
  ASSERT_NO_FATAL_FAILURE(kill_station_mid_cut());
  ASSERT_NO_FATAL_FAILURE(restart_postgres_during_wave_2());
  ASSERT_NO_FATAL_FAILURE(restart_station_and_broker());
  // Everything settles: 60 jobs, each done or held, every batch cut or held, the watch folders empty.
  ASSERT_TRUE(wait_until([&] {
    return jobs_in("") == kScans && jobs_in("WHERE state NOT IN ('done', 'held')") == 0 &&
           shop_.count("SELECT count(*) FROM batches WHERE state NOT IN ('cut', 'held', 'dissolved')") == 0 &&
           scans_waiting() == 0;
  }, 180)) << jobs_in("WHERE state NOT IN ('done', 'held')") << " jobs unfinished" << shop_.log_tails();
  for (const std::string& node : kNodes) EXPECT_EQ(shop_.stop_node(node), 0) << node << shop_.log_tails();
  shop_.stop_cutter("cutter-a");
  shop_.stop_cutter("cutter-b");
  check_jobs_and_events();
  check_cut_bytes();
}

}  // namespace
}  // namespace lastcut::daemon::testing
