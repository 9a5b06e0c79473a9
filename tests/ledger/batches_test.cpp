// Batches: only the station that owns a cutter claims its batches; a cut marks the jobs done; a
// batch whose station vanished while sending is held with its jobs and never offered again,
// while one merely claimed goes back to the queue.
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
  auto first = compute_->make_batch(10);
  ASSERT_TRUE(first.ok() && first->has_value()) << first.error();
  EXPECT_EQ(query("SELECT count(*) FROM jobs WHERE batch_id = " + std::to_string(**first)), "2");
  auto second = compute_->make_batch(10);
  ASSERT_TRUE(second.ok() && second->has_value());
  auto none = compute_->make_batch(10);
  ASSERT_TRUE(none.ok());
  EXPECT_FALSE(none->has_value());

  auto by_compute = compute_->claim_batch(30);  // owns no cutter
  ASSERT_TRUE(by_compute.ok());
  EXPECT_FALSE(by_compute->has_value());
  auto claim = station1_->claim_batch(30);
  ASSERT_TRUE(claim.ok() && claim->has_value()) << claim.error();
  EXPECT_EQ((*claim)->batch_id, **first);
  EXPECT_EQ((*claim)->cutter, "cutter-1");
  EXPECT_EQ((*claim)->job_ids.size(), 2u);
  auto nothing_more = station1_->claim_batch(30);
  ASSERT_TRUE(nothing_more.ok());
  EXPECT_FALSE(nothing_more->has_value());

  EXPECT_EQ(station1_->mark_cut((*claim)->lease).error(),
            "batch " + std::to_string(**first) + " is claimed, not sending");
  ASSERT_TRUE(station1_->mark_sending((*claim)->lease).ok());
  ASSERT_TRUE(station1_->mark_cut((*claim)->lease).ok());
  EXPECT_EQ(query("SELECT string_agg(state, ',' ORDER BY id) FROM jobs"), "done,done,batched");

  auto other = station2_->claim_batch(30);
  ASSERT_TRUE(other.ok() && other->has_value());
  EXPECT_EQ((*other)->batch_id, **second);
}

TEST_F(BatchesTest, StationVanishedWhileSendingIsHeldNeverRequeued) {
  ASSERT_TRUE(compute_->make_batch(10).ok());
  auto claim = station1_->claim_batch(0.3);
  ASSERT_TRUE(claim.ok() && claim->has_value());
  ASSERT_TRUE(station1_->mark_sending((*claim)->lease).ok());
  std::this_thread::sleep_for(std::chrono::milliseconds(600));  // station-1 stops answering

  auto swept = compute_->sweep_expired(3);
  ASSERT_TRUE(swept.ok()) << swept.error();
  EXPECT_EQ(swept->batches_held, std::vector<long long>{(*claim)->batch_id});
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
  ASSERT_TRUE(compute_->make_batch(10).ok());
  auto claim = station1_->claim_batch(0.3);
  ASSERT_TRUE(claim.ok() && claim->has_value());
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  auto swept = compute_->sweep_expired(3);
  ASSERT_TRUE(swept.ok());
  EXPECT_EQ(swept->batches_requeued, std::vector<long long>{(*claim)->batch_id});
  auto again = station1_->claim_batch(30);
  ASSERT_TRUE(again.ok() && again->has_value());
  EXPECT_EQ((*again)->batch_id, (*claim)->batch_id);
  EXPECT_EQ((*again)->lease.epoch, 2);
  EXPECT_FALSE(station1_->mark_sending((*claim)->lease).ok());  // the old claim's epoch
  EXPECT_TRUE(station1_->mark_sending((*again)->lease).ok());
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
