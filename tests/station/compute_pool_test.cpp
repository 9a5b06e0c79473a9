// ComputePool (daemon/station/compute_pool.hpp) against a fake ComputeStore, the one fake: the
// engine steps are the real ones (molds of a generated 3000-triangle last, a strip nesting with
// the real machine profile), so what comes back to a claim is what a spool or a ledger would
// record. Each rule of the pool fails its own case when broken: the claim gets exactly one
// outcome, an engine refusal is an outcome and not a crash, a store's trouble is one log line per
// change, a material no longer configured fails the nesting without the engine, wake() ends an
// idle wait, and stop() lets the step in hand finish while unclaimed work stays in the store.
#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <fstream>
#include <future>
#include <mutex>
#include <sstream>
#include <utility>

#include "daemon/station/compute_pool.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "tests/station/log_lines.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut::daemon {
namespace {

using Calls = std::vector<std::string>;

// Hands out `queue` one claim at a time and records, in order, each claim and each outcome:
// "claim compute-1", "molds job-1 computed", "molds job-2 failed: <reason>", "nest batch-1 made: placed job-1".
class FakeComputeStore : public ComputeStore {
 public:
  struct Work {
    std::optional<MoldsWork> molds;
    std::optional<NestWork> nest;
  };

  void add(Work work) {
    std::lock_guard lock(mutex_);
    queue_.push_back(std::move(work));
  }
  void fail_claims_with(std::string error) {
    std::lock_guard lock(mutex_);
    claim_error_ = std::move(error);
  }
  Calls calls() const {
    std::lock_guard lock(mutex_);
    return calls_;
  }
  std::size_t left() const {
    std::lock_guard lock(mutex_);
    return queue_.size();
  }
  // Waits up to `seconds` until `count` calls are recorded.
  bool wait_for_calls(std::size_t count, double seconds) {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return calls_.size() >= count; });
  }
  std::function<void()> while_computing;  // runs in the worker as a claim's work is handed out
  JobMolds last_molds;
  NestResult last_nest;

  Result<std::optional<ComputeClaim>> claim(const std::string& worker) override {
    std::optional<Work> work;
    {
      std::lock_guard lock(mutex_);
      record("claim " + worker);
      if (!claim_error_.empty()) return Status::failure(claim_error_);
      if (queue_.empty()) return std::optional<ComputeClaim>();
      work = std::move(queue_.front());
      queue_.pop_front();
    }
    if (while_computing) while_computing();
    if (work->molds) return std::optional<ComputeClaim>(std::make_unique<FakeMoldsClaim>(*this, std::move(*work->molds)));
    return std::optional<ComputeClaim>(std::make_unique<FakeNestClaim>(*this, std::move(*work->nest)));
  }

 private:
  class FakeMoldsClaim : public MoldsClaim {
   public:
    FakeMoldsClaim(FakeComputeStore& store, MoldsWork work) : store_(store), work_(std::move(work)) {}
    const MoldsWork& work() const override { return work_; }
    void finish(const JobMolds& molds) override {
      const char* verdict = molds.verdict == JobMolds::Verdict::Computed        ? "computed"
                            : molds.verdict == JobMolds::Verdict::HeldForReview ? "held"
                                                                                : "failed";
      std::lock_guard lock(store_.mutex_);
      store_.last_molds = molds;
      store_.record("molds " + work_.label + " " + verdict + (molds.reason.empty() ? "" : ": " + molds.reason));
    }

   private:
    FakeComputeStore& store_;
    MoldsWork work_;
  };

  class FakeNestClaim : public NestClaim {
   public:
    FakeNestClaim(FakeComputeStore& store, NestWork work) : store_(store), work_(std::move(work)) {}
    const NestWork& work() const override { return work_; }
    void finish(const NestResult& result) override {
      std::string placed;
      for (const std::string& id : result.placed) placed += " " + id;
      std::lock_guard lock(store_.mutex_);
      store_.last_nest = result;
      store_.record("nest " + work_.label + (result.made ? " made: placed" + placed : " failed: " + result.made.error()));
    }

   private:
    FakeComputeStore& store_;
    NestWork work_;
  };

  void record(std::string call) {
    calls_.push_back(std::move(call));
    changed_.notify_all();
  }

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Work> queue_;
  Calls calls_;
  std::string claim_error_;
};

using testing::LogLines;

// One calf strip and one HPGL plotter, with the project's machine profiles.
std::shared_ptr<const DaemonConfig> shop_config() {
  auto config = std::make_shared<DaemonConfig>();
  config->paths.machines_dir = std::filesystem::path(LASTCUT_SOURCE_DIR) / "config" / "machines";
  config->batch.nest_time_s = 0.5;
  MaterialConfig calf;
  calf.width_mm = 800;
  calf.length_mm = 1200;
  calf.spacing_mm = 3;
  config->materials["calf"] = calf;
  CutterSection plotter;
  plotter.machine = "hpgl-pen-plotter";
  config->cutters["plotter-1"] = plotter;
  return config;
}

class ComputePoolTest : public ::testing::Test {
 protected:
  // A job folder holding a generated last, as a store's claim would give it.
  MoldsWork job(const std::string& id) {
    const std::filesystem::path dir = folder_ / id;
    std::filesystem::create_directories(dir);
    LastParams params = LastParams::for_eu_size(40, FootSide::Left);
    params.target_triangles = 3000;
    params.seed = 7;
    write_mesh(dir / "last.stl", generate_last(params).mesh);
    return MoldsWork{dir / "last.stl", dir, JobTicket{}, id};
  }

  test::TempDir folder_{"compute-pool"};
  FakeComputeStore store_;
  ProgressMonitor monitor_;
  std::shared_ptr<const DaemonConfig> config_ = shop_config();
  ComputePool pool_{store_, monitor_, [this] { return config_; }, ComputePoolTiming{30.0, 30.0}};
};

TEST_F(ComputePoolTest, AClaimedJobGetsItsMoldsAndExactlyOneOutcome) {
  store_.add({job("job-1"), std::nullopt});
  EXPECT_TRUE(pool_.turn("compute-1"));
  EXPECT_EQ(store_.calls(), (Calls{"claim compute-1", "molds job-1 computed"}));
  EXPECT_EQ(store_.last_molds.molds, 2);  // medial and lateral half
  EXPECT_EQ(store_.last_molds.pieces, 2);
  EXPECT_TRUE(std::filesystem::exists(folder_ / "job-1" / "items.json"));
  EXPECT_EQ(monitor_.stuck(ProgressMonitor::Clock::now() + std::chrono::hours(24)), "")
      << "the worker's watchdog bracket is left open";
  EXPECT_FALSE(pool_.turn("compute-1"));  // nothing left: no outcome without a claim
  EXPECT_EQ(store_.calls().size(), 3u);
}

TEST_F(ComputePoolTest, ACutOffScanIsAFailedOutcomeWithTheEnginesReasonAndThePoolGoesOn) {
  MoldsWork broken = job("job-2");
  std::filesystem::resize_file(broken.scan, 1000);  // a binary STL cut off mid-triangle
  store_.add({broken, std::nullopt});
  store_.add({job("job-3"), std::nullopt});
  EXPECT_TRUE(pool_.turn("compute-1"));
  EXPECT_TRUE(pool_.turn("compute-1"));
  const Calls calls = store_.calls();
  ASSERT_EQ(calls.size(), 4u);
  EXPECT_EQ(calls[1].rfind("molds job-2 failed: ", 0), 0u) << calls[1];
  EXPECT_NE(calls[1].find("last.stl"), std::string::npos) << "the reason names the file: " << calls[1];
  EXPECT_EQ(calls[3], "molds job-3 computed");
}

TEST_F(ComputePoolTest, AStoreThatCannotBeAskedIsOneLogLinePerChangeNotPerTry) {
  LogLines log;
  store_.fail_claims_with("ledger unreachable: connection refused");
  for (int i = 0; i < 5; ++i) EXPECT_FALSE(pool_.turn("compute-" + std::to_string(1 + i % 2)));
  EXPECT_EQ(pool_.trouble(), "ledger unreachable: connection refused");
  store_.fail_claims_with("");
  EXPECT_FALSE(pool_.turn("compute-1"));
  EXPECT_FALSE(pool_.turn("compute-2"));
  EXPECT_EQ(pool_.trouble(), "");
  EXPECT_EQ(log.count("compute workers: ledger unreachable: connection refused"), 1);
  EXPECT_EQ(log.count("compute workers: the store answers again"), 1);
}

TEST_F(ComputePoolTest, AStripBatchIsNestedIntoItsFolderAndEveryJobIsPlaced) {
  store_.add({job("job-4"), std::nullopt});
  store_.add({job("job-5"), std::nullopt});
  ASSERT_TRUE(pool_.turn("compute-1"));
  ASSERT_TRUE(pool_.turn("compute-1"));
  const std::filesystem::path batch_dir = folder_ / "batch-1";
  std::filesystem::create_directories(batch_dir);
  NestWork batch{"batch-1", "calf", "plotter-1", {}, batch_dir, "", ""};
  for (const char* id : {"job-4", "job-5"}) batch.jobs.push_back({id, folder_ / id, JobTicket{}});
  store_.add({std::nullopt, batch});
  ASSERT_TRUE(pool_.turn("compute-1"));
  EXPECT_EQ(store_.calls().back(), "nest batch-1 made: placed job-4 job-5");
  EXPECT_EQ(store_.last_nest.pieces, 4);
  EXPECT_GT(store_.last_nest.utilisation, 0.0);
  ASSERT_FALSE(store_.last_nest.cut_file.empty());
  EXPECT_TRUE(std::filesystem::exists(batch_dir / store_.last_nest.cut_file));
  EXPECT_EQ(monitor_.stuck(ProgressMonitor::Clock::now() + std::chrono::hours(24)), "");
}

TEST_F(ComputePoolTest, ABatchOfAMaterialNoLongerConfiguredFailsAsAWholeWithoutTheEngine) {
  const std::filesystem::path batch_dir = folder_ / "batch-2";
  std::filesystem::create_directories(batch_dir);
  store_.add({std::nullopt, NestWork{"batch-2", "suede", "plotter-1", {{"job-6", folder_ / "job-6", JobTicket{}}},
                                     batch_dir, "", ""}});
  ASSERT_TRUE(pool_.turn("compute-1"));
  EXPECT_EQ(store_.calls().back(), "nest batch-2 failed: material suede is not configured (any more)");
  EXPECT_TRUE(store_.last_nest.placed.empty());
  EXPECT_TRUE(std::filesystem::is_empty(batch_dir));
}

TEST_F(ComputePoolTest, WakeEndsAnIdleWaitAtOnce) {
  pool_.start(1);
  ASSERT_TRUE(store_.wait_for_calls(1, 10));  // asked, found nothing: now waits its 30 s idle time
  store_.add({job("job-7"), std::nullopt});
  pool_.wake();
  EXPECT_TRUE(store_.wait_for_calls(3, 20)) << "the worker slept through wake()";
  pool_.stop();
  EXPECT_EQ(store_.calls()[2], "molds job-7 computed");
}

TEST_F(ComputePoolTest, StopLetsTheStepInHandFinishAndLeavesUnclaimedWorkInTheStore) {
  store_.add({job("job-8"), std::nullopt});
  store_.add({job("job-9"), std::nullopt});
  std::promise<void> computing;
  bool told = false;
  store_.while_computing = [&] {
    if (!std::exchange(told, true)) computing.set_value();
  };
  pool_.start(1);
  computing.get_future().wait();
  pool_.stop();  // while job-8's molds are being made
  EXPECT_EQ(store_.calls(), (Calls{"claim compute-1", "molds job-8 computed"}));
  EXPECT_EQ(store_.left(), 1u);
}

}  // namespace
}  // namespace lastcut::daemon
