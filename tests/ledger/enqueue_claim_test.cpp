// Entering scans and claiming them: one job per scan across nodes, and two nodes racing for the
// same queue claim every job exactly once.
#include <algorithm>
#include <set>
#include <thread>

#include "tests/ledger/ledger_fixture.hpp"

namespace lastcut::test {
namespace {

using EnqueueClaimTest = LedgerTest;

TEST_F(EnqueueClaimTest, TheSameScanOnTwoNodesIsOneJob) {
  auto a = client("node-a");
  auto b = client("node-b");
  ASSERT_TRUE(a && b);
  auto first = a->enqueue(scan(7));
  ASSERT_TRUE(first.ok()) << first.error();
  EXPECT_FALSE(first->duplicate);
  EXPECT_EQ(first->state, "ready");
  ledger::ScanEntry again = scan(7);
  again.scan_name = "copy-of-7.stl";
  auto second = b->enqueue(again);
  ASSERT_TRUE(second.ok()) << second.error();
  EXPECT_TRUE(second->duplicate);
  EXPECT_EQ(second->job_id, first->job_id);
  EXPECT_EQ(second->origin, "node-a");
  EXPECT_EQ(query("SELECT count(*) FROM jobs"), "1");
  EXPECT_EQ(query("SELECT scan_name FROM jobs"), "scan-7.stl");
  EXPECT_EQ(query("SELECT string_agg(event || '@' || node, ',' ORDER BY id) FROM job_events"),
            "entered@node-a,duplicate@node-b");
}

TEST_F(EnqueueClaimTest, KnownBytesAreHeldOrEnteredAgainByTheDuplicatePolicy) {
  auto a = client("node-a");
  ASSERT_TRUE(a);
  auto first = a->enqueue(scan(7));
  ASSERT_TRUE(first.ok()) << first.error();
  ledger::ScanEntry again = scan(7);
  again.scan_name = "copy-of-7.stl";
  auto held = a->enqueue(again, ledger::OnDuplicate::Hold);
  ASSERT_TRUE(held.ok()) << held.error();
  EXPECT_TRUE(held->duplicate);
  EXPECT_NE(held->job_id, first->job_id);
  EXPECT_EQ(held->duplicate_of, first->job_id);
  EXPECT_EQ(held->state, "held");
  EXPECT_EQ(held->reason, "same scan bytes as job " + std::to_string(first->job_id) + " (duplicate held by policy)");
  auto processed = a->enqueue(again, ledger::OnDuplicate::Process);
  ASSERT_TRUE(processed.ok()) << processed.error();
  EXPECT_EQ(processed->state, "ready");
  EXPECT_EQ(processed->duplicate_of, first->job_id);
  EXPECT_EQ(query("SELECT string_agg(state || ':' || coalesce(duplicate_of::text, '-'), ',' ORDER BY id) FROM jobs"),
            "ready:-,held:" + std::to_string(first->job_id) + ",ready:" + std::to_string(first->job_id));
  // The duplicate processed again computes into a folder of its own (its sidecar may differ).
  auto claimed = a->claim_job(30);
  ASSERT_TRUE(claimed.ok() && claimed->has_value());
  EXPECT_EQ((*claimed)->job_folder, scan(7).scan_sha256);
  auto second = a->claim_job(30);
  ASSERT_TRUE(second.ok() && second->has_value());
  EXPECT_EQ((*second)->job_folder, scan(7).scan_sha256 + "-" + std::to_string(processed->job_id));
  // The held one is processed after `lastcut requeue`.
  EXPECT_TRUE(a->requeue_held(held->job_id).ok());
  EXPECT_EQ(query("SELECT state FROM jobs WHERE id = " + std::to_string(held->job_id)), "ready");
}

TEST_F(EnqueueClaimTest, OldestReadyJobFirstAndNothingWhenEmpty) {
  auto a = client("node-a");
  ASSERT_TRUE(a);
  auto none = a->claim_job(30);
  ASSERT_TRUE(none.ok()) << none.error();
  EXPECT_FALSE(none->has_value());
  std::vector<long long> ids;
  for (int n : {3, 1, 2}) {
    auto entered = a->enqueue(scan(n));
    ASSERT_TRUE(entered.ok()) << entered.error();
    ids.push_back(entered->job_id);
  }
  for (long long expected : ids) {
    auto claim = a->claim_job(30);
    ASSERT_TRUE(claim.ok() && claim->has_value()) << claim.error();
    EXPECT_EQ((*claim)->job_id, expected);
    EXPECT_EQ((*claim)->attempts, 1);
    EXPECT_EQ((*claim)->lease.epoch, 1);
  }
}

TEST_F(EnqueueClaimTest, TwoNodesRacingClaimEachOfHundredJobsExactlyOnce) {
  constexpr int kJobs = 100;
  {
    auto feeder = client("feeder");
    ASSERT_TRUE(feeder);
    for (int n = 0; n < kJobs; ++n) ASSERT_TRUE(feeder->enqueue(scan(n)).ok());
  }
  std::vector<std::vector<long long>> claimed(2);
  std::vector<std::string> errors(2);
  std::vector<std::thread> nodes;
  for (int i = 0; i < 2; ++i) {
    nodes.emplace_back([&, i] {
      auto connected = ledger::LedgerClient::connect(url_, i == 0 ? "node-a" : "node-b");
      if (!connected) {
        errors[i] = connected.error();
        return;
      }
      auto& node = **connected;
      for (;;) {
        auto claim = node.claim_job(30);
        if (!claim) {
          errors[i] = claim.error();
          return;
        }
        if (!claim->has_value()) return;
        claimed[i].push_back((*claim)->job_id);
        if (Status done = node.mark_computed((*claim)->lease); !done) {
          errors[i] = done.error();
          return;
        }
      }
    });
  }
  for (auto& node : nodes) node.join();
  EXPECT_EQ(errors[0], "");
  EXPECT_EQ(errors[1], "");
  std::set<long long> all(claimed[0].begin(), claimed[0].end());
  for (long long id : claimed[1]) EXPECT_TRUE(all.insert(id).second) << "job " << id << " claimed twice";
  EXPECT_EQ(claimed[0].size() + claimed[1].size(), static_cast<std::size_t>(kJobs));
  EXPECT_EQ(all.size(), static_cast<std::size_t>(kJobs));
  // The ledger's own account agrees: every job computed after exactly one claim.
  EXPECT_EQ(query("SELECT count(*) FROM jobs WHERE state = 'computed' AND attempts = 1"), std::to_string(kJobs));
  EXPECT_EQ(query("SELECT count(*) FROM leases WHERE epoch = 1 AND holder IS NULL"), std::to_string(kJobs));
  EXPECT_EQ(query("SELECT count(*) FROM job_events WHERE event = 'claimed'"), std::to_string(kJobs));
}

TEST_F(EnqueueClaimTest, OperatorRequeuesOnlyHeldJobs) {
  auto a = client("node-a");
  ASSERT_TRUE(a);
  auto entered = a->enqueue(scan(1));
  ASSERT_TRUE(entered.ok());
  Status refused = a->requeue_held(entered->job_id);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error(), "job " + std::to_string(entered->job_id) + " is ready, neither held nor failed: nothing to requeue");
  Status missing = a->requeue_held(999);
  EXPECT_EQ(missing.error(), "no job 999 in the ledger");
}

}  // namespace
}  // namespace lastcut::test
