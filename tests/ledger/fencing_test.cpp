// Leases and fencing: an expired lease goes back to the queue, a node whose lease was taken over
// cannot change the job any more, a node restarted under its name gets its jobs requeued, and a
// scan that keeps killing its computation fails after max_attempts.
#include <chrono>
#include <thread>

#include "tests/ledger/ledger_fixture.hpp"

namespace lastcut::test {
namespace {

using FencingTest = LedgerTest;

constexpr double kShortLease_s = 0.3;

TEST_F(FencingTest, NodeWhoseLeaseWasTakenOverIsRefused) {
  HeldJob held;
  ASSERT_NO_FATAL_FAILURE(hold_one_job(kShortLease_s, held));
  auto& [a, b, claim_a] = held;
  const ledger::Lease lease_a = claim_a.lease;

  // Before expiry nobody else may take it.
  auto early = b->sweep_expired(3);
  ASSERT_TRUE(early.ok()) << early.error();
  EXPECT_TRUE(early->jobs_requeued.empty());
  auto nothing = b->claim_job(30);
  ASSERT_TRUE(nothing.ok());
  EXPECT_FALSE(nothing->has_value());

  auto swept = sweep_after_expiry(*b, kShortLease_s);  // node-a "pauses" past its lease
  ASSERT_TRUE(swept.ok()) << swept.error();
  EXPECT_EQ(swept->jobs_requeued, std::vector<long long>{lease_a.object_id});
  auto claim_b = b->claim_job(30);
  ASSERT_TRUE(claim_b.ok() && claim_b->has_value()) << claim_b.error();
  EXPECT_EQ((*claim_b)->job_id, lease_a.object_id);
  EXPECT_EQ((*claim_b)->lease.epoch, lease_a.epoch + 1);
  EXPECT_EQ((*claim_b)->attempts, 2);

  // node-a wakes up: every state change and the renewal are refused.
  const std::string lost = "lease lost: job " + std::to_string(lease_a.object_id) +
                           " is now held by node-b (epoch 2, this node's claim was epoch 1)";
  EXPECT_EQ(a->mark_computed(lease_a).error(), lost);
  EXPECT_EQ(a->mark_failed(lease_a, "late").error(), lost);
  EXPECT_EQ(a->renew(lease_a, 30).error(), lost);
  EXPECT_EQ(query("SELECT state FROM jobs"), "computing");

  ASSERT_TRUE(b->mark_computed((*claim_b)->lease).ok());
  EXPECT_EQ(query("SELECT state FROM jobs"), "computed");
  EXPECT_EQ(query("SELECT string_agg(event || '@' || node, ',' ORDER BY id) FROM job_events"),
            "entered@node-a,claimed@node-a,requeued@node-b,claimed@node-b,computed@node-b");
}

TEST_F(FencingTest, RenewedLeaseSurvivesTheSweep) {
  HeldJob held;
  ASSERT_NO_FATAL_FAILURE(hold_one_job(kShortLease_s, held));
  auto& [a, b, claim] = held;
  for (int beat = 0; beat < 4; ++beat) {
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    ASSERT_TRUE(a->renew(claim.lease, kShortLease_s).ok());
    auto swept = b->sweep_expired(3);
    ASSERT_TRUE(swept.ok());
    EXPECT_TRUE(swept->jobs_requeued.empty()) << "beat " << beat;
  }
  EXPECT_TRUE(a->mark_computed(claim.lease).ok());
}

TEST_F(FencingTest, ExpiredAndSweptWithoutNewClaimStillRefusesTheOldHolder) {
  HeldJob held;
  ASSERT_NO_FATAL_FAILURE(hold_one_job(kShortLease_s, held));
  auto& [a, b, claim] = held;
  ASSERT_TRUE(sweep_after_expiry(*b, kShortLease_s).ok());
  EXPECT_EQ(a->mark_computed(claim.lease).error(),
            "lease lost: job " + std::to_string(claim.job_id) + " went back to the queue after this node's lease expired");
  EXPECT_EQ(query("SELECT state FROM jobs"), "ready");
}

TEST_F(FencingTest, ScanInterruptedMaxAttemptsTimesFails) {
  auto b = client("node-b");
  ASSERT_TRUE(b);
  ASSERT_TRUE(b->enqueue(scan(1)).ok());
  for (int attempt = 1; attempt <= 2; ++attempt) {
    auto a = client("node-a");
    auto claim = a->claim_job(kShortLease_s);
    ASSERT_TRUE(claim.ok() && claim->has_value());
    EXPECT_EQ((*claim)->attempts, attempt);
    auto swept = sweep_after_expiry(*b, kShortLease_s, 2);
    ASSERT_TRUE(swept.ok());
    EXPECT_EQ(swept->jobs_requeued.size(), attempt == 1 ? 1u : 0u);
    EXPECT_EQ(swept->jobs_failed.size(), attempt == 2 ? 1u : 0u);
  }
  EXPECT_EQ(query("SELECT state || ': ' || reason FROM jobs"),
            "failed: the computation was interrupted 2 times (last on node-a)");
}

TEST_F(FencingTest, RestartedNodeHandsBackWhatItsLastRunHeld) {
  long long job_id = 0;
  {
    HeldJob crashed;
    ASSERT_NO_FATAL_FAILURE(hold_one_job(3600, crashed));  // a long lease: only the restart can free it
    job_id = crashed.claim.job_id;
  }
  auto restarted = client("node-a");
  ASSERT_TRUE(restarted);
  auto recovered = restarted->register_node({"compute"}, {}, 3);
  ASSERT_TRUE(recovered.ok()) << recovered.error();
  EXPECT_EQ(recovered->jobs_requeued, std::vector<long long>{job_id});
  EXPECT_EQ(query("SELECT state FROM jobs"), "ready");
  EXPECT_EQ(query("SELECT array_to_string(roles, ',') FROM nodes WHERE name = 'node-a'"), "compute");
}

}  // namespace
}  // namespace lastcut::test
