// Station (daemon/station/station.hpp) against a fake StationStore: the order of start and stop,
// the intake of the watch folder (a real HotFolder on a real folder, inotify), SIGHUP, and how the
// store's links reach the station's workers. The stores themselves are tested through the real
// binary in station_behaviour_test.cpp; here each rule of the station fails its own case.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <mutex>
#include <thread>

#include "daemon/station/station.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut::daemon {
namespace {

using Calls = std::vector<std::string>;

// Records the station's calls in order; its compute store and its one cutter's store never have work.
class FakeStationStore : public StationStore {
 public:
  class NoCompute : public ComputeStore {
   public:
    Result<std::optional<ComputeClaim>> claim(const std::string&) override { return std::optional<ComputeClaim>(); }
  };
  class NoCuts : public CutStore {
   public:
    std::optional<std::string> next_batch() override { return std::nullopt; }
    Result<std::optional<CutOrder>> claim() override { return std::optional<CutOrder>(); }
    Status mark_sending(const CutOrder&) override { return Status::success(); }
    CutEnd record_end(const CutOrder&, CutEnd end, const std::string&, const std::vector<std::string>&) override {
      return end;
    }
  };

  Intake answer = Intake::Taken;  // what take_scan says
  StationLinks links;
  NoCompute compute;
  NoCuts cuts;

  Calls calls() const {
    std::lock_guard lock(mutex_);
    return calls_;
  }
  int offers(const std::string& file) const {
    const Calls seen = calls();
    return static_cast<int>(std::count(seen.begin(), seen.end(), "take_scan " + file));
  }

  Status open(const StationLinks& given) override {
    links = given;
    record("open");
    return Status::success();
  }
  ComputeStore* compute_store() override {
    record("compute_store");
    return &compute;
  }
  ComputePoolTiming compute_timing() const override { return {30.0, 30.0}; }
  std::vector<StationCutter> cutters() override {
    record("cutters");
    return {{"plotter-1", &cuts, {"plotter-1", "idle", "", "", 0, 0, 0, 0}}};
  }
  Intake take_scan(const ReadyScan& ready) override {
    record("take_scan " + ready.scan.filename().string());
    return answer;
  }
  Intake take_hide(const ReadyScan& ready) override {
    record("take_hide " + ready.scan.filename().string());
    return Intake::Taken;
  }
  void tick(Clock::time_point) override {}
  std::string where() const override { return "a fake store"; }
  std::string status_line() const override { return "fake: 0 job(s)"; }
  void stopping() override { record("stopping"); }
  void close() override { record("close"); }

 private:
  void record(std::string call) {
    std::lock_guard lock(mutex_);
    calls_.push_back(std::move(call));
  }
  mutable std::mutex mutex_;
  Calls calls_;
};

class StationTest : public ::testing::Test {
 protected:
  StationTest() {
    auto config = std::make_shared<DaemonConfig>();
    config->paths.watch_dir = folder_ / "incoming";
    config->watch.mode = WatchMode::Inotify;
    config->watch.rescan_interval_s = 60;  // no full listing during a case: only events bring files
    config->watch.stable_checks = 1;
    config->watch.stable_interval_s = 0.05;
    config->watch.incomplete_grace_s = 0.1;
    config->jobs.stop_grace_s = 1;
    config->cutters["plotter-1"] = CutterSection{};
    config_ = config;
  }

  // Builds the station; the fake store stays reachable through store_.
  std::unique_ptr<Station> make_station() {
    return std::make_unique<Station>(config_, [this](const RunningConfig& running) {
      running_ = &running;
      auto store = std::make_unique<FakeStationStore>();
      store_ = store.get();
      return store;
    });
  }
  void drop(const std::string& name) {
    std::ofstream(folder_ / "incoming" / name) << "solid x\nendsolid x\n";
  }
  // Runs the main loop's turn until `done` or `seconds` pass.
  template <typename Done>
  bool run_until(Station& station, double seconds, Done done) {
    const auto deadline = JobFlow::Clock::now() + std::chrono::duration<double>(seconds);
    while (JobFlow::Clock::now() < deadline) {
      station.read_events();
      station.tick(JobFlow::Clock::now());
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
  }

  test::TempDir folder_{"station"};
  std::shared_ptr<const DaemonConfig> config_;
  FakeStationStore* store_ = nullptr;
  const RunningConfig* running_ = nullptr;
};

TEST_F(StationTest, StartsInOneOrderAndStopsInTheReverse) {
  auto station = make_station();
  ASSERT_TRUE(station->start());
  EXPECT_TRUE(std::filesystem::is_directory(folder_ / "incoming")) << "the watch folder is made at start";
  station->stop();
  EXPECT_EQ(store_->calls(), (Calls{"open", "cutters", "compute_store", "stopping", "close"}));
}

TEST_F(StationTest, AStableFileIsOfferedToTheStoreOnceAndForgottenWhenTaken) {
  auto station = make_station();
  ASSERT_TRUE(station->start());
  drop("a.stl");
  ASSERT_TRUE(run_until(*station, 10, [&] { return store_->offers("a.stl") >= 1; }));
  // Still in the folder (a fake store takes nothing away), but forgotten: not offered again (until
  // the folder's next full listing, a minute away).
  run_until(*station, 0.5, [] { return false; });
  EXPECT_EQ(store_->offers("a.stl"), 1);
}

TEST_F(StationTest, WhileTheStoreCannotTakeFilesTheyWaitAndAreOfferedAgain) {
  auto station = make_station();
  ASSERT_TRUE(station->start());
  store_->answer = StationStore::Intake::Later;
  drop("b.stl");
  ASSERT_TRUE(run_until(*station, 10, [&] { return store_->offers("b.stl") >= 1; }));
  run_until(*station, 0.5, [] { return false; });
  EXPECT_EQ(store_->offers("b.stl"), 1) << "offered again before the retry time: the store is hammered";
  store_->answer = StationStore::Intake::Taken;
  EXPECT_TRUE(run_until(*station, 10, [&] { return store_->offers("b.stl") >= 2; }))
      << "a file the store could not take was forgotten, not offered again";
}

TEST_F(StationTest, TheStoresLinksReachTheCutterWorkerAndTheStatusLineNamesIt) {
  auto station = make_station();
  ASSERT_TRUE(station->start());
  EXPECT_EQ(store_->links.cutter_condition("plotter-1"), "idle");
  EXPECT_EQ(station->status_line(), "fake: 0 job(s); plotter-1: idle");
  store_->links.wake_cutter("plotter-1");  // must not block or throw
  store_->links.wake_compute();
}

TEST_F(StationTest, SighupReachesTheStoreThroughTheRunningConfigurationItWasGiven) {
  auto station = make_station();
  ASSERT_TRUE(station->start());
  auto next = std::make_shared<DaemonConfig>(*config_);
  next->batch.window_s = 42;
  EXPECT_EQ(station->reload(next), "");
  EXPECT_EQ(running_->get()->batch.window_s, 42);
}

}  // namespace
}  // namespace lastcut::daemon
