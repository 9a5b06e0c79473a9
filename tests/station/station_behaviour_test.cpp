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
//  - `lastcut status` lists a held job under "held" with its reason, and a cut job among the recent.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <iterator>
#include <set>
#include <sstream>

#include "tests/daemon/daemon_harness.hpp"
#include "tests/daemon/hide_samples.hpp"
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

INSTANTIATE_TEST_SUITE_P(BothStores, StationBehaviour, ::testing::Values(StoreKind::Spool, StoreKind::Ledger),
                         [](const ::testing::TestParamInfo<StoreKind>& store) {
                           return store.param == StoreKind::Spool ? "Spool" : "Ledger";
                         });

}  // namespace
}  // namespace lastcut::daemon::testing
