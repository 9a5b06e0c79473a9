// Batches: only the station that owns a cutter claims its batches; a cut marks the jobs done; a
// batch whose station vanished while sending is held with its jobs and never offered again,
// while one merely claimed goes back to the queue.
#include <algorithm>
#include <chrono>
#include <thread>

#include "tests/ledger/ledger_fixture.hpp"

namespace lastcut::test {
namespace {

class BatchesTest : public LedgerTest {
 protected:
  // Two computed jobs on cutter-1 (owned by station-1) and one on cutter-2 (station-2).
  void SetUp() override {
    LedgerTest::SetUp();
    if (HasFatalFailure()) return;
    compute_ = client("compute");
    station1_ = client("station-1");
    station2_ = client("station-2");
    ASSERT_TRUE(compute_ && station1_ && station2_);
    ASSERT_TRUE(compute_->register_node({"compute"}, {}, 3).ok());
    auto registered = station1_->register_node({"station"}, {"cutter-1"}, 3);
    ASSERT_TRUE(registered.ok()) << registered.error();
    ASSERT_TRUE(station2_->register_node({"station"}, {"cutter-2"}, 3).ok());
    for (int n : {1, 2, 3}) {
      ASSERT_TRUE(compute_->enqueue(scan(n, n == 3 ? "cutter-2" : "cutter-1")).ok());
      auto claim = compute_->claim_job(30);
      ASSERT_TRUE(claim.ok() && claim->has_value());
      ASSERT_TRUE(compute_->mark_computed((*claim)->lease).ok());
    }
  }

  std::unique_ptr<ledger::LedgerClient> compute_, station1_, station2_;
};

TEST_F(BatchesTest, OnlyTheOwningStationClaimsAndCutMarksJobsDone) {
  const std::optional<long long> first = nest_batch(*compute_, 10);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(query("SELECT count(*) FROM jobs WHERE batch_id = " + std::to_string(*first)), "2");
  const std::optional<long long> second = nest_batch(*compute_, 10);
  ASSERT_TRUE(second.has_value());
  EXPECT_FALSE(nest_batch(*compute_, 10).has_value());

  auto by_compute = compute_->claim_batch(30);  // owns no cutter
  ASSERT_TRUE(by_compute.ok());
  EXPECT_FALSE(by_compute->has_value());
  auto claim = station1_->claim_batch(30);
  ASSERT_TRUE(claim.ok() && claim->has_value()) << claim.error();
  EXPECT_EQ((*claim)->batch_id, *first);
  EXPECT_EQ((*claim)->cutter, "cutter-1");
  EXPECT_EQ((*claim)->job_ids.size(), 2u);
  EXPECT_EQ((*claim)->cut_file, "batches/" + std::to_string(*first) + "/cut.nc");
  auto nothing_more = station1_->claim_batch(30);
  ASSERT_TRUE(nothing_more.ok());
  EXPECT_FALSE(nothing_more->has_value());

  EXPECT_EQ(station1_->mark_cut((*claim)->lease).error(),
            "batch " + std::to_string(*first) + " is claimed, not sending");
  ASSERT_TRUE(station1_->mark_sending((*claim)->lease).ok());
  ASSERT_TRUE(station1_->mark_cut((*claim)->lease).ok());
  EXPECT_EQ(query("SELECT string_agg(state, ',' ORDER BY id) FROM jobs"), "done,done,batched");

  auto other = station2_->claim_batch(30);
  ASSERT_TRUE(other.ok() && other->has_value());
  EXPECT_EQ((*other)->batch_id, *second);
}

TEST_F(BatchesTest, StationVanishedWhileSendingIsHeldNeverRequeued) {
  ASSERT_TRUE(nest_batch(*compute_, 10).has_value());
  auto claim = station1_->claim_batch(0.3);
  ASSERT_TRUE(claim.ok() && claim->has_value());
  ASSERT_TRUE(station1_->mark_sending((*claim)->lease).ok());
  std::this_thread::sleep_for(std::chrono::milliseconds(600));  // station-1 stops answering

  auto swept = compute_->sweep_expired(3);
  ASSERT_TRUE(swept.ok()) << swept.error();
  EXPECT_EQ(swept->batches_held, std::vector<long long>{(*claim)->batch_id});
  ASSERT_EQ(swept->jobs_held.size(), 2u) << "the held batch's jobs, for the status events";
  std::sort(swept->jobs_held.begin(), swept->jobs_held.end(),
            [](const ledger::HeldJob& a, const ledger::HeldJob& b) { return a.job_id < b.job_id; });
  EXPECT_EQ(swept->jobs_held[0].scan_name, "scan-1.stl");
  EXPECT_EQ(swept->jobs_held[1].batch_id, (*claim)->batch_id);
  EXPECT_EQ(swept->jobs_held[1].cutter, "cutter-1");
  EXPECT_TRUE(swept->batches_requeued.empty());
  const std::string reason = "station station-1 stopped answering while sending batch " +
                             std::to_string((*claim)->batch_id) + ": check the cutter's table, then lastcut requeue";
  EXPECT_EQ(query("SELECT state || ': ' || reason FROM batches"), "held: " + reason);
  EXPECT_EQ(query("SELECT count(*) FROM jobs WHERE state = 'held' AND reason = $r$" + reason + "$r$"), "2");

  // Never offered again, and the vanished station's late report changes nothing.
  auto again = station1_->claim_batch(30);
  ASSERT_TRUE(again.ok());
  EXPECT_FALSE(again->has_value());
  EXPECT_FALSE(station1_->mark_cut((*claim)->lease).ok());
  EXPECT_EQ(query("SELECT state FROM batches"), "held");

  // The operator hands a held job back: it is computed again.
  const long long job = (*claim)->job_ids.front();
  ASSERT_TRUE(compute_->requeue_held(job).ok());
  EXPECT_EQ(query("SELECT state || coalesce(batch_id::text, '-') FROM jobs WHERE id = " + std::to_string(job)),
            "ready-");
}

TEST_F(BatchesTest, ClaimedButNotSendingGoesBackToTheQueue) {
  ASSERT_TRUE(nest_batch(*compute_, 10).has_value());
  auto claim = station1_->claim_batch(0.3);
  ASSERT_TRUE(claim.ok() && claim->has_value());
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  auto swept = compute_->sweep_expired(3);
  ASSERT_TRUE(swept.ok());
  EXPECT_EQ(swept->batches_requeued, std::vector<long long>{(*claim)->batch_id});
  auto again = station1_->claim_batch(30);
  ASSERT_TRUE(again.ok() && again->has_value());
  EXPECT_EQ((*again)->batch_id, (*claim)->batch_id);
  EXPECT_EQ((*again)->lease.epoch, (*claim)->lease.epoch + 1);  // nesting, first claim, this one
  EXPECT_FALSE(station1_->mark_sending((*claim)->lease).ok());  // the old claim's epoch
  EXPECT_TRUE(station1_->mark_sending((*again)->lease).ok());
}

TEST_F(BatchesTest, AComputedJobWaitsForCompanyUpToTheWindow) {
  // cutter-1 has 2 computed jobs: fewer than 3, so they wait for the window...
  auto early = compute_->make_batch(batch_rule(0.5, 3), 30);
  ASSERT_TRUE(early.ok()) << early.error();
  EXPECT_FALSE(early->has_value());
  // ... unless the group is full,
  auto full = compute_->make_batch(batch_rule(0.5, 2), 30);
  ASSERT_TRUE(full.ok() && full->has_value());
  EXPECT_EQ((*full)->job_ids.size(), 2u);
  EXPECT_EQ((*full)->job_folders, (std::vector<std::string>{scan(1).scan_sha256, scan(2).scan_sha256}));
  EXPECT_EQ(query("SELECT state FROM batches WHERE id = " + std::to_string((*full)->batch_id)), "nesting");
  // ... or the oldest has waited long enough (cutter-2's single job).
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  auto late = compute_->make_batch(batch_rule(0.5, 3), 30);
  ASSERT_TRUE(late.ok() && late->has_value());
  EXPECT_EQ((*late)->cutter, "cutter-2");
}

TEST_F(BatchesTest, NestedRejectsFailAloneAndAnEmptyBatchIsDissolved) {
  auto made = compute_->make_batch(group_now(10), 30);
  ASSERT_TRUE(made.ok() && made->has_value());
  const auto& ids = (*made)->job_ids;
  ASSERT_EQ(ids.size(), 2u);
  ASSERT_TRUE(compute_->mark_nested((*made)->lease, {"batches/x/cut.nc", 3, {{ids[0], "a mold is wider"}}}).ok());
  EXPECT_EQ(query("SELECT state || ':' || coalesce(batch_id::text, '-') || ':' || coalesce(reason, '') FROM jobs"
                  " WHERE id = " + std::to_string(ids[0])),
            "failed:-:a mold is wider");
  EXPECT_EQ(query("SELECT state || ':' || cut_file || ':' || pieces FROM batches"), "queued:batches/x/cut.nc:3");

  auto alone = compute_->make_batch(group_now(10), 30);  // cutter-2's job, which cannot be placed at all
  ASSERT_TRUE(alone.ok() && alone->has_value());
  ASSERT_TRUE(compute_->mark_nested((*alone)->lease, {"", 0, {{(*alone)->job_ids[0], "too wide"}}}).ok());
  EXPECT_EQ(query("SELECT state FROM batches WHERE id = " + std::to_string((*alone)->batch_id)), "dissolved");
  auto nothing = station2_->claim_batch(30);
  ASSERT_TRUE(nothing.ok());
  EXPECT_FALSE(nothing->has_value());
}

TEST_F(BatchesTest, ABatchThatCouldNotBeMadeHoldsItsJobsForTheOperator) {
  auto made = compute_->make_batch(group_now(10), 30);
  ASSERT_TRUE(made.ok() && made->has_value());
  const auto& ids = (*made)->job_ids;
  ASSERT_EQ(ids.size(), 2u);
  ledger::NestedBatch nested;
  nested.reason = "batch could not be made: no machine profile";
  for (long long id : ids) nested.held.emplace_back(id, nested.reason);
  ASSERT_TRUE(compute_->mark_nested((*made)->lease, nested).ok());
  EXPECT_EQ(query("SELECT string_agg(state || ':' || coalesce(batch_id::text, '-') || ':' || reason, ',' ORDER BY id)"
                  " FROM jobs WHERE id IN (" + std::to_string(ids[0]) + ", " + std::to_string(ids[1]) + ")"),
            "held:-:batch could not be made: no machine profile,held:-:batch could not be made: no machine profile");
  EXPECT_EQ(query("SELECT state FROM batches WHERE id = " + std::to_string((*made)->batch_id)), "dissolved");
  ASSERT_TRUE(compute_->requeue_held(ids[0]).ok());
  EXPECT_EQ(query("SELECT state FROM jobs WHERE id = " + std::to_string(ids[0])), "ready");
}

TEST_F(BatchesTest, ANestingNodeThatVanishesLeavesItsJobsToBeRegrouped) {
  auto made = compute_->make_batch(group_now(10), 0.3);
  ASSERT_TRUE(made.ok() && made->has_value());
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  auto swept = station1_->sweep_expired(3);
  ASSERT_TRUE(swept.ok()) << swept.error();
  EXPECT_EQ(swept->batches_dissolved, std::vector<long long>{(*made)->batch_id});
  EXPECT_EQ(query("SELECT string_agg(state, ',' ORDER BY id) FROM jobs"), "computed,computed,computed");
  // The late node's result is refused; another node groups the jobs anew.
  EXPECT_FALSE(compute_->mark_nested((*made)->lease, {"batches/x/cut.nc", 2, {}}).ok());
  const std::optional<long long> again = nest_batch(*station1_, 10);
  ASSERT_TRUE(again.has_value());
  EXPECT_NE(*again, (*made)->batch_id);
}

TEST_F(BatchesTest, AStationClaimsPerCutterAndABatchNotTakenByTheCutterIsQueuedAgain) {
  ASSERT_TRUE(station1_->register_node({"station"}, {"cutter-1", "cutter-3"}, 3).ok());
  ASSERT_TRUE(nest_batch(*compute_, 10).has_value());  // cutter-1
  auto other_cutter = station1_->claim_batch(30, "cutter-3");
  ASSERT_TRUE(other_cutter.ok());
  EXPECT_FALSE(other_cutter->has_value());
  auto claim = station1_->claim_batch(30, "cutter-1");
  ASSERT_TRUE(claim.ok() && claim->has_value());
  ASSERT_TRUE(station1_->mark_sending((*claim)->lease).ok());
  ASSERT_TRUE(station1_->mark_not_sent((*claim)->lease, "alarm: door open").ok());
  EXPECT_EQ(query("SELECT state || ': ' || reason FROM batches"), "queued: alarm: door open");
  auto again = station1_->claim_batch(30, "cutter-1");
  ASSERT_TRUE(again.ok() && again->has_value());
  EXPECT_EQ((*again)->batch_id, (*claim)->batch_id);
}

TEST_F(BatchesTest, ACutterCabledToARunningStationIsRefusedElsewhere) {
  auto refused = station2_->register_node({"station"}, {"cutter-1"}, 3);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error(),
            "cutter cutter-1 is cabled to station station-1, which is running: remove [cutters.cutter-1] from one of "
            "the two configurations");
}

}  // namespace
}  // namespace lastcut::test
