// The lease heartbeat: kept leases outlive lease_s, dropped ones run out, a lease taken over is
// reported lost, a database outage is logged once each way while renewals resume after it, and an
// outage shorter than the lease costs a live node nothing (no backoff, the sweep's grace).
#include <chrono>
#include <mutex>
#include <thread>

#include "daemon/ledger/lease_keeper.hpp"
#include "tests/ledger/ledger_fixture.hpp"

namespace lastcut::test {
namespace {

using LeaseKeeperTest = LedgerTest;

struct Lines {
  std::mutex mutex;
  std::vector<std::string> lines;
  ledger::LeaseKeeper::Log sink() {
    return [this](const std::string& line) {
      std::lock_guard lock(mutex);
      lines.push_back(line);
    };
  }
  std::vector<std::string> copy() {
    std::lock_guard lock(mutex);
    return lines;
  }
};

void sleep_s(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }

TEST_F(LeaseKeeperTest, KeptLeaseOutlivesLeaseTimeDroppedOneRunsOut) {
  constexpr double kLease_s = 0.5;
  HeldJob held;
  ASSERT_NO_FATAL_FAILURE(hold_one_job(kLease_s, held));
  auto& [a, b, claim] = held;
  Lines log;
  {
    ledger::LeaseKeeper keeper(url_, "node-a", kLease_s, 0.1, log.sink());
    keeper.keep(claim.lease);
    for (int i = 0; i < 6; ++i) {
      sleep_s(0.25);
      auto swept = b->sweep_expired(3);
      ASSERT_TRUE(swept.ok()) << swept.error();
      EXPECT_TRUE(swept->jobs_requeued.empty()) << "after " << (i + 1) * 0.25 << " s";
    }
    EXPECT_FALSE(keeper.lost(claim.lease));
    keeper.drop(claim.lease);
    auto swept = sweep_after_expiry(*b, kLease_s);
    ASSERT_TRUE(swept.ok());
    EXPECT_EQ(swept->jobs_requeued, std::vector<long long>{claim.job_id});
  }
  EXPECT_TRUE(log.copy().empty());
}

TEST_F(LeaseKeeperTest, LeaseTakenOverIsReportedLost) {
  HeldJob held;
  ASSERT_NO_FATAL_FAILURE(hold_one_job(30, held));
  auto& [a, b, claim] = held;
  Lines log;
  ledger::LeaseKeeper keeper(url_, "node-a", 30, 0.1, log.sink());
  keeper.keep(claim.lease);
  {
    // Another node's claim, as if node-a had paused past its lease.
    pqxx::connection connection(url_);
    pqxx::work tx(connection);
    tx.exec("UPDATE leases SET holder = 'node-b', epoch = epoch + 1");
    tx.commit();
  }
  for (int i = 0; i < 50 && !keeper.lost(claim.lease); ++i) sleep_s(0.05);
  EXPECT_TRUE(keeper.lost(claim.lease));
  EXPECT_EQ(log.copy(), std::vector<std::string>{"lease lost: job " + std::to_string(claim.job_id) +
                                                 " is now held by node-b (epoch 2, this node's claim was epoch 1)"});
}

TEST_F(LeaseKeeperTest, OutageIsLoggedOnceEachWayAndRenewalsResume) {
  HeldJob held;
  ASSERT_NO_FATAL_FAILURE(hold_one_job(30, held));
  auto& [a, b, claim] = held;
  Lines log;
  // A lease longer than the outage and the server's restart (an expired lease is never renewed).
  ledger::LeaseKeeper keeper(url_, "node-a", 6, 0.1, log.sink());
  keeper.keep(claim.lease);
  sleep_s(0.3);
  ASSERT_TRUE(server_.stop().empty());
  sleep_s(1.5);  // several heartbeats and retries while down
  EXPECT_FALSE(keeper.reachable());
  ASSERT_TRUE(server_.start().empty());
  for (int i = 0; i < 100 && !keeper.reachable(); ++i) sleep_s(0.05);
  EXPECT_TRUE(keeper.reachable());
  EXPECT_FALSE(keeper.lost(claim.lease));
  const auto lines = log.copy();
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("leases not renewed, retrying: ledger unreachable while ", 0), 0u)
      << lines[0];
  EXPECT_EQ(lines[1], "ledger reachable again, leases renewed");
  // The renewed lease still fences: node-a can finish the job.
  // (node-a's own connection died with the server: the call connects again by itself.)
  const Status computed = a->mark_computed(claim.lease);
  EXPECT_TRUE(computed.ok()) << computed.error();
}

TEST_F(LeaseKeeperTest, ALeaseOutlivesAnOutageShorterThanItsLengthWhileAnotherNodeSweeps) {
  // The defaults scaled down by ten, the outage longer: lease 6 s, heartbeat 0.5 s, the database
  // away for 4 s plus its restart. A keeper that backed off (0.5, 1, 2, 4 s...) would try again
  // only after the lease ran out, and node-b's sweep would take the job.
  constexpr double kLease_s = 6, kHeartbeat_s = 0.5;
  HeldJob held;
  ASSERT_NO_FATAL_FAILURE(hold_one_job(kLease_s, held));
  auto& [a, b, claim] = held;
  Lines log;
  ledger::LeaseKeeper keeper(url_, "node-a", kLease_s, kHeartbeat_s, log.sink());
  keeper.keep(claim.lease);
  sleep_s(0.6);
  ASSERT_TRUE(server_.stop().empty());
  sleep_s(4);
  ASSERT_TRUE(server_.start().empty());
  std::vector<long long> taken;
  for (int i = 0; i < 25; ++i) {  // node-b sweeps as a node does, with the grace of one heartbeat
    auto swept = b->sweep_expired(3, kHeartbeat_s);
    if (swept) taken.insert(taken.end(), swept->jobs_requeued.begin(), swept->jobs_requeued.end());
    sleep_s(0.1);
  }
  EXPECT_TRUE(taken.empty()) << "node-a was alive all along; its job was taken back";
  EXPECT_FALSE(keeper.lost(claim.lease));
  const Status computed = a->mark_computed(claim.lease);
  EXPECT_TRUE(computed.ok()) << computed.error();
}

TEST_F(LeaseKeeperTest, TheSweepsGraceTakesBackOnlyLeasesExpiredLongerThanIt) {
  HeldJob held;
  ASSERT_NO_FATAL_FAILURE(hold_one_job(0.3, held));
  auto& [a, b, claim] = held;
  sleep_s(0.5);  // expired 0.2 s ago
  auto swept = b->sweep_expired(3, 5);
  ASSERT_TRUE(swept.ok()) << swept.error();
  EXPECT_TRUE(swept->jobs_requeued.empty());
  swept = b->sweep_expired(3, 0);
  ASSERT_TRUE(swept.ok()) << swept.error();
  EXPECT_EQ(swept->jobs_requeued, std::vector<long long>{claim.job_id});
}

}  // namespace
}  // namespace lastcut::test
