// The behaviours a station must show whichever store keeps its jobs, each run against the spool of
// one station and against the shop's PostgreSQL ledger (issue #33): the real lastcutd, a simulated
// HPGL plotter on a pty, real folders, and for the ledger a real PostgreSQL and mosquitto started
// by the test. Each behaviour is the station's: take it out of either store and its case fails there.
//  - [jobs] duplicate_policy: bytes already cut are held for an operator, `lastcut requeue` cuts them;
//    with "process" they are cut again as a job of their own.
//  - [batch] window_s: a job computed later joins the batch of one that waits for company.
//  - [batch] max_pieces: a batch closes when its pieces reach the limit, without waiting the window.
//  - SIGHUP: a shorter window applies to jobs already waiting.
//  - a hide loaded while no job waits stays on its table, and the next job of its material is cut on it.
//  - [hides] at most 64 jobs (kHideMaxJobs) are offered to one hide, the oldest; the rest wait for
//    the next hide, however high their priority.
//  - `lastcut status` lists a held job under "held" with its reason, and a cut job among the recent.
//  - a batch whose record this lastcutd cannot trust is held with its job and the reason, never cut
//    (spool: batch.json with an unknown stage; ledger: `sending` left by a vanished node).
//  - at most once across SIGKILL: a batch being sent when lastcutd dies is held with its job after
//    the restart, and the plotter never receives its cut file again.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <iterator>
#include <set>
#include <sstream>

#include "tests/daemon/daemon_harness.hpp"
#include "tests/daemon/hide_samples.hpp"
#include "daemon/station/hide_policy.hpp"
#include "tests/station/station_under_test.hpp"

namespace lastcut::daemon::testing {
namespace {

class StationBehaviour : public ::testing::TestWithParam<StoreKind> {
 protected:
  std::unique_ptr<StationUnderTest> start(const std::string& name, const StationSettings& settings) {
    auto station = StationUnderTest::make(GetParam(), name, settings);
    const std::string trouble = station->start();
    EXPECT_EQ(trouble, "");
    return station;
  }
  static bool reached(const StationUnderTest& station, const std::string& scan, const std::string& state) {
    return station.job(scan).state == state;
  }
  bool spool() const { return GetParam() == StoreKind::Spool; }
};

// The rows `lastcut status` prints under the heading that starts with `heading`: the indented lines
// up to the next heading.
std::vector<std::string> rows_under(const std::string& status, const std::string& heading) {
  std::vector<std::string> rows;
  std::istringstream lines(status);
  bool under = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("  ", 0) != 0) under = line.rfind(heading, 0) == 0;
    else if (under) rows.push_back(line);
  }
  return rows;
}

// Whether one of `rows` is the row of `job`: its id first, its scan name a word of its own, and
// ending with `reason` (both stores print the reason last).
bool lists(const std::vector<std::string>& rows, const SeenJob& job, const std::string& reason) {
  for (const std::string& row : rows) {
    std::istringstream words(row);
    std::vector<std::string> seen{std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
    if (seen.empty() || seen.front() != job.id || std::find(seen.begin(), seen.end(), job.scan) == seen.end()) continue;
    const auto end = row.find_last_not_of(' ');
    const std::string text = end == std::string::npos ? "" : row.substr(0, end + 1);
    if (text.size() >= reason.size() && text.compare(text.size() - reason.size(), reason.size(), reason) == 0) return true;
  }
  return false;
}

constexpr const char* kHeldHeading = "held (waiting for an operator: lastcut requeue ID):";

TEST_P(StationBehaviour, ADuplicateIsHeldByPolicyAndCutAfterARequeue) {
  StationSettings settings;
  settings.duplicate_policy = "hold";
  auto station = start("behaviour-duplicate", settings);
  station->drop_scan("first.stl", "dup");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "first.stl", "done"); }, 90)) << station->log();
  station->drop_copy("dup", "again.stl");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "again.stl", "held"); }, 30)) << station->log();
  const SeenJob held = station->job("again.stl");
  EXPECT_EQ(held.reason, "same scan bytes as job " + station->job("first.stl").id + " (duplicate held by policy)");
  EXPECT_EQ(station->requeue(held.id), 0);
  ASSERT_TRUE(wait_until([&] { return reached(*station, "again.stl", "done"); }, 90)) << station->log();
  EXPECT_EQ(station->stop(), 0);
}

TEST_P(StationBehaviour, ADuplicateIsCutAgainWhenThePolicyIsProcess) {
  StationSettings settings;
  settings.duplicate_policy = "process";
  auto station = start("behaviour-process", settings);
  station->drop_scan("first.stl", "dup");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "first.stl", "done"); }, 90)) << station->log();
  station->drop_copy("dup", "again.stl", "order = \"B-2\"\n");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "again.stl", "done"); }, 90)) << station->log();
  EXPECT_NE(station->job("again.stl").id, station->job("first.stl").id);
  EXPECT_NE(station->job("again.stl").batch, station->job("first.stl").batch);
  EXPECT_EQ(station->stop(), 0);
}

TEST_P(StationBehaviour, AJobComputedLaterJoinsABatchWaitingForItsWindow) {
  StationSettings settings;
  settings.window_s = 8;
  auto station = start("behaviour-window", settings);
  station->drop_scan("early.stl", "early");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "early.stl", "computed"); }, 60)) << station->log();
  station->drop_scan("late.stl", "late");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "early.stl", "done") && reached(*station, "late.stl", "done"); },
                         90))
      << station->log();
  EXPECT_EQ(station->job("early.stl").batch, station->job("late.stl").batch);
  EXPECT_EQ(station->stop(), 0);
}

TEST_P(StationBehaviour, ABatchClosesAtMaxPiecesWithoutWaitingItsWindow) {
  StationSettings settings;
  settings.window_s = 600;  // never reached by the test
  settings.max_pieces = 2;  // a small last gives two molds: one job fills a batch
  auto station = start("behaviour-pieces", settings);
  station->drop_scan("one.stl", "one");
  station->drop_scan("two.stl", "two");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "one.stl", "done") && reached(*station, "two.stl", "done"); }, 90))
      << station->log();
  EXPECT_NE(station->job("one.stl").batch, station->job("two.stl").batch);
  EXPECT_EQ(station->stop(), 0);
}

TEST_P(StationBehaviour, AWindowOfZeroNestsEachJobAloneAtOnce) {
  StationSettings settings;
  settings.window_s = 0;  // docs/daemon.md: each job nested alone, at once
  settings.max_pieces = 0;
  auto station = start("behaviour-alone", settings);
  // Dropped together: on a ledger node the one compute worker claims all three scans before it
  // forms a batch, so all three wait together; still each is nested alone.
  for (const char* name : {"one", "two", "three"}) station->drop_scan(std::string(name) + ".stl", name);
  ASSERT_TRUE(wait_until([&] {
    return reached(*station, "one.stl", "done") && reached(*station, "two.stl", "done") &&
           reached(*station, "three.stl", "done");
  }, 120)) << station->log();
  const std::set<std::string> batches{station->job("one.stl").batch, station->job("two.stl").batch,
                                      station->job("three.stl").batch};
  EXPECT_EQ(batches.size(), 3u) << station->log();
  EXPECT_EQ(station->stop(), 0);
}

TEST_P(StationBehaviour, AReloadedWindowAppliesToJobsAlreadyWaiting) {
  StationSettings settings;
  settings.window_s = 600;
  auto station = start("behaviour-reload", settings);
  station->drop_scan("waiting.stl", "waiting");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "waiting.stl", "computed"); }, 60)) << station->log();
  std::this_thread::sleep_for(std::chrono::seconds(2));
  ASSERT_EQ(station->job("waiting.stl").state, "computed");  // waiting for company
  station->edit_config("window_s = 600.000000", "window_s = 0");
  station->signal(SIGHUP);
  ASSERT_TRUE(wait_until([&] { return station->log().find("configuration reloaded") != std::string::npos; }, 10))
      << station->log();
  EXPECT_EQ(station->log().find("kept the running value"), std::string::npos) << station->log();
  ASSERT_TRUE(wait_until([&] { return reached(*station, "waiting.stl", "done"); }, 60)) << station->log();
  EXPECT_EQ(station->stop(), 0);
}

TEST_P(StationBehaviour, AJobWhoseBatchCannotBeMadeIsHeldUntilRequeued) {
  auto station = start("behaviour-unmade", StationSettings{});
  // A machine profile that does not exist: no cut file can be made, which is not the job's fault.
  station->edit_config("machine = \"hpgl-pen-plotter\"", "machine = \"no-such-machine\"");
  station->signal(SIGHUP);
  ASSERT_TRUE(wait_until([&] { return station->log().find("configuration reloaded") != std::string::npos; }, 10))
      << station->log();
  station->drop_scan("unmade.stl", "unmade");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "unmade.stl", "held"); }, 90)) << station->log();
  const SeenJob held = station->job("unmade.stl");
  EXPECT_NE(held.reason.find("could not be made"), std::string::npos) << held.reason;
  EXPECT_NE(held.reason.find("no-such-machine"), std::string::npos) << held.reason;
  // Mended: the job is handed back and cut.
  station->edit_config("machine = \"no-such-machine\"", "machine = \"hpgl-pen-plotter\"");
  station->signal(SIGHUP);
  std::this_thread::sleep_for(std::chrono::seconds(1));
  EXPECT_EQ(station->requeue(held.id), 0);
  ASSERT_TRUE(wait_until([&] { return reached(*station, "unmade.stl", "done"); }, 90)) << station->log();
  EXPECT_EQ(station->stop(), 0);
}

TEST_P(StationBehaviour, AHideLoadedWhileNothingWaitsStaysOnItsTable) {
  StationSettings settings;
  settings.hides = true;
  auto station = start("behaviour-hide", settings);
  const auto staging = station->config_file().parent_path() / "staging";
  std::filesystem::create_directories(staging);
  std::filesystem::create_directories(station->hides());
  write_hide_json(staging / "H-1.json", 1500, 1000);
  write_text(station->hides() / "H-1.toml", "id = \"H-1\"\n");
  drop(staging / "H-1.json", station->hides(), "H-1.json");
  ASSERT_TRUE(wait_until([&] { return station->hide_state("H-1") == "loaded"; }, 20)) << station->log();
  std::this_thread::sleep_for(std::chrono::seconds(2));
  EXPECT_EQ(station->hide_state("H-1"), "loaded") << station->log();
  station->drop_scan("leather.stl", "leather", "material = \"leather\"\n");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "leather.stl", "done"); }, 90)) << station->log();
  EXPECT_EQ(station->hide_state("H-1"), "used");
  EXPECT_EQ(station->stop(), 0);
}

TEST_P(StationBehaviour, StatusShowsAHeldJobWithItsReasonAndACutJobAmongTheRecent) {
  StationSettings settings;
  settings.duplicate_policy = "hold";
  auto station = start("behaviour-status", settings);
  station->drop_scan("first.stl", "shown");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "first.stl", "done"); }, 90)) << station->log();
  station->drop_copy("shown", "again.stl");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "again.stl", "held"); }, 30)) << station->log();
  const SeenJob cut = station->job("first.stl"), held = station->job("again.stl");
  const std::string status = station->status();
  const auto held_rows = rows_under(status, kHeldHeading);
  EXPECT_TRUE(lists(held_rows, held, "same scan bytes as job " + cut.id + " (duplicate held by policy)")) << status;
  EXPECT_FALSE(lists(held_rows, cut, "")) << status;
  EXPECT_TRUE(lists(rows_under(status, "recent:"), cut, "")) << status;
  EXPECT_EQ(station->stop(), 0);
}

// At most kHideMaxJobs (64) jobs go on one hide, the oldest; the rest wait for the next hide. 64
// small generated lasts of leather (molds in about 0.1 s each), then "urgent.stl" with the highest
// priority, the newest job: the nester would place it first, yet H-1 is not offered it. H-1 (as big as
// the plotter's work area) takes the first pieces that fit, the other offered jobs wait with "did not
// fit on hide H-1"; urgent.stl waits without having been offered, and is cut on the next hide, H-2.
TEST_P(StationBehaviour, AtMost64JobsGoOnOneHideAndTheRestWaitForTheNext) {
  StationSettings settings;
  settings.hides = true;
  auto station = start("behaviour-hide-cap", settings);
  const auto staging = station->config_file().parent_path() / "staging";
  std::filesystem::create_directories(staging);
  std::filesystem::create_directories(station->hides());
  const auto leather = [&] {
    std::vector<SeenJob> found;
    for (const SeenJob& job : station->jobs())
      if (job.scan.rfind("cap-", 0) == 0) found.push_back(job);
    return found;
  };
  for (int i = 0; i < kHideMaxJobs; ++i) {
    const std::string tag = "cap-" + std::to_string(i);
    station->drop_scan(tag + ".stl", tag, "material = \"leather\"\n");
  }
  ASSERT_TRUE(wait_until([&] { return leather().size() == static_cast<std::size_t>(kHideMaxJobs); }, 60))
      << station->log();
  station->drop_scan("urgent.stl", "urgent", "material = \"leather\"\npriority = 9\n");
  const auto all_computed = [&] {
    const auto jobs = leather();
    return reached(*station, "urgent.stl", "computed") &&
           std::all_of(jobs.begin(), jobs.end(), [](const SeenJob& job) { return job.state == "computed"; });
  };
  ASSERT_TRUE(wait_until(all_computed, 90)) << station->log();
  // Hides inside the plotter's 1189 x 841 mm work area (a bigger one is refused at nesting).
  const auto load_hide = [&](const std::string& id, double length_mm) {
    write_hide_json(staging / (id + ".json"), length_mm, 800);
    write_text(station->hides() / (id + ".toml"), "id = \"" + id + "\"\n");
    drop(staging / (id + ".json"), station->hides(), id + ".json");
  };
  load_hide("H-1", 1150);
  ASSERT_TRUE(wait_until([&] { return station->hide_state("H-1") == "used"; }, 60)) << station->log();
  const std::string did_not_fit = "waiting for a hide of leather: did not fit on hide H-1";
  std::string hide_batch;
  const auto offered_to_h1 = [&](const SeenJob& job) {
    return (job.state == "done" && job.batch == hide_batch) ||
           (job.state == "computed" && job.batch.empty() && job.reason.rfind(did_not_fit, 0) == 0);
  };
  // The hide's batch is cut; the offered jobs that did not fit wait again.
  ASSERT_TRUE(wait_until(
      [&] {
        const auto jobs = leather();
        for (const SeenJob& job : jobs)
          if (job.state == "done") hide_batch = job.batch;
        return !hide_batch.empty() && std::all_of(jobs.begin(), jobs.end(), offered_to_h1);
      },
      60))
      << station->log();
  const SeenJob urgent = station->job("urgent.stl");
  EXPECT_EQ(urgent.state, "computed");
  EXPECT_EQ(urgent.batch, "");
  EXPECT_EQ(urgent.reason.find("H-1"), std::string::npos) << urgent.reason;

  // H-2 is cut to the same outline as H-1: the same bytes under another ID must be a hide of its own.
  load_hide("H-2", 1150);
  ASSERT_TRUE(wait_until([&] { return reached(*station, "urgent.stl", "done"); }, 60)) << station->log();
  EXPECT_NE(station->job("urgent.stl").batch, hide_batch);
  EXPECT_EQ(station->hide_state("H-2"), "used");
  EXPECT_EQ(station->stop(), 0);
}

// A record of a batch this lastcutd cannot trust is held with its job for an operator, never cut.
// On the spool: batch.json with a stage this lastcutd does not know ('xyz', a newer lastcutd or a
// hand edit). The ledger cannot keep such a row (CHECK constraints on every state column; a ledger
// of a newer schema refuses an older node at start), so there it is what the ledger CAN have: a
// batch left `sending` by a node that vanished (its lease ran out). A well-formed queued batch left
// beside it is cut: the plotter takes what it is sent.
TEST_P(StationBehaviour, ABatchWhoseRecordCannotBeTrustedIsHeldAndNeverCut) {
  auto station = start("behaviour-untrusted", StationSettings{});
  ASSERT_EQ(station->stop(), 0);
  const std::string untrusted =
      station->leave_batch(LeftBatch::Untrusted, "untrusted.stl", "IN;SP1;PU0,0;PD222,0;PU;SP0;\n");
  station->leave_batch(LeftBatch::Queued, "queued.stl", "IN;SP1;PU0,0;PD333,0;PU;SP0;\n");
  ASSERT_EQ(station->restart(), "");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "untrusted.stl", "held") && reached(*station, "queued.stl", "done"); },
                         30))
      << station->log();
  const std::string reason =
      spool() ? "batch " + untrusted + ": batch.json has an unknown stage 'xyz'; not sent, an operator must check it"
              : "station station-gone stopped answering while sending batch " + untrusted +
                    ": check the cutter's table, then lastcut requeue";
  const SeenJob held = station->job("untrusted.stl");
  EXPECT_EQ(held.reason, reason);
  EXPECT_EQ(station->batch_state(untrusted), "held");
  const std::string status = station->status();
  EXPECT_TRUE(lists(rows_under(status, kHeldHeading), held, reason)) << status;
  EXPECT_EQ(station->stop(), 0);
  station->stop_cutter();
  const auto runs = station->received_per_run();
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(count_occurrences(runs[0], "PD222"), 0) << runs[0];
  EXPECT_EQ(count_occurrences(runs[0], "PD333"), 1) << runs[0];
}

// At most once across a crash: lastcutd SIGKILLed while its plotter takes a batch (the plotter hangs
// at line 20) and started again holds the batch and its job with the reason, and never sends the
// cut file again: the plotter (switched off and on: a new simulator run) gets only the next batch.
TEST_P(StationBehaviour, ABatchBeingSentWhenLastcutdIsKilledIsHeldAndNeverSentAgain) {
  StationSettings settings;
  settings.cutter_fault = "stall-at-line=20";
  auto station = start("behaviour-killed", settings);
  station->drop_scan("killed.stl", "killed");
  // Killed once the plotter has taken the batch's first lines (the simulator writes its record twice a
  // second): `sending` is written before the first byte goes out.
  ASSERT_TRUE(wait_until(
      [&] {
        return station->batch_state(station->job("killed.stl").batch) == "sending" &&
               !station->received_per_run().back().empty();
      },
      90))
      << station->log();
  const std::string batch = station->job("killed.stl").batch;
  station->kill();
  ASSERT_EQ(station->start_cutter(), "");
  ASSERT_EQ(station->restart(), "");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "killed.stl", "held"); }, 30)) << station->log();
  EXPECT_EQ(station->job("killed.stl").reason,
            spool() ? "lastcutd stopped (crash or power cut) while batch " + batch +
                          " was being sent to cutter cutter-1; pieces may be partly cut"
                    : "station station-a stopped answering while sending batch " + batch +
                          ": check the cutter's table, then lastcut requeue");
  EXPECT_EQ(station->batch_state(batch), "held");
  // The station cuts again after its restart; a held batch sent again would come before this one.
  station->drop_scan("after.stl", "after");
  ASSERT_TRUE(wait_until([&] { return reached(*station, "after.stl", "done"); }, 90)) << station->log();
  EXPECT_EQ(station->stop(), 0);
  station->stop_cutter();

  const std::string cut = station->cut_file(batch);
  ASSERT_GT(cut.size(), 200u);
  const auto runs = station->received_per_run();
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(count_occurrences(runs[0], cut), 0) << "the stalled cut never completed";
  EXPECT_FALSE(runs[0].empty());  // what reached the stalled plotter before the kill: the cut's beginning
  EXPECT_LT(runs[0].size(), cut.size());
  EXPECT_EQ(cut.compare(0, runs[0].size(), runs[0]), 0) << runs[0];
  EXPECT_EQ(runs[1], station->cut_file(station->job("after.stl").batch)) << "after the restart: only the next batch";
}

INSTANTIATE_TEST_SUITE_P(BothStores, StationBehaviour, ::testing::Values(StoreKind::Spool, StoreKind::Ledger),
                         [](const ::testing::TestParamInfo<StoreKind>& store) {
                           return store.param == StoreKind::Spool ? "Spool" : "Ledger";
                         });

}  // namespace
}  // namespace lastcut::daemon::testing
