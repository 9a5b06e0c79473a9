// Finished work waits for a ledger that is away (daemon/ledger_node/ledger_journal.hpp
// change_once_reachable): computed molds and a nested batch finished while the real PostgreSQL
// server is stopped 10 s are written as soon as it is back, by the node that made them, without
// waiting for a lease to run out, and nothing is computed or nested twice (the ledger's events); a
// cut through 25 s of the default 30 s lease is marked cut, nothing held; late molds after a
// takeover are refused (scaled down by five: that case waits out a whole lease). And the sweep of
// batch folders no row uses any more (daemon/ledger_node/orphan_sweep.hpp).
#include <atomic>
#include <chrono>
#include <thread>

#include "daemon/job/job_ticket.hpp"
#include "daemon/ledger/lease_keeper.hpp"
#include "daemon/ledger_node/ledger_compute_store.hpp"
#include "daemon/ledger_node/ledger_cut_store.hpp"
#include "daemon/ledger_node/ledger_journal.hpp"
#include "daemon/ledger_node/orphan_sweep.hpp"
#include "engine/core/durable_file.hpp"
#include "tests/ledger/ledger_fixture.hpp"
#include "tests/station/log_lines.hpp"

namespace lastcut::test {
namespace {


using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

class FinishedWorkOutageTest : public LedgerTest {
 protected:
  void SetUp() override {
    LedgerTest::SetUp();
    shared_root_ = server_.folder() / "shared";
    std::filesystem::remove_all(shared_root_);
    shared_ = std::make_unique<daemon::SharedStore>(shared_root_);
    ASSERT_TRUE(shared_->prepare().ok());
    ledger_.url = url_;
    ledger_.node = "node-a";
    ledger_.roles = {"compute"};
    ledger_.shared_dir = shared_root_;
    ledger_.lease_s = lease_s_;
    ledger_.heartbeat_s = heartbeat_s_;
    auto settings = std::make_shared<daemon::DaemonConfig>();
    settings->batch.window_s = 0;  // each computed job is a batch at once
    settings_ = settings;
    entering_ = client("node-a");
    ASSERT_TRUE(entering_);
    daemon::JobTicket ticket;
    ticket.material = "calf";
    ticket.cutter = "cutter-1";
    ledger::ScanEntry entry = scan(1);
    entry.ticket = daemon::ticket_to_json(ticket).dump();
    ASSERT_TRUE(entering_->enqueue(entry).ok());
    keeper_ = std::make_unique<ledger::LeaseKeeper>(url_, "node-a", lease_s_, heartbeat_s_, [](const std::string&) {});
    store_ = std::make_unique<daemon::LedgerComputeStore>(ledger_, *shared_, *keeper_, [this] { return settings_; },
                                                          journal_, [this](double seconds) { return pause(seconds); });
  }

  // How the node waits while finished work waits for the ledger: a real wait, and while a test
  // holds the gate, no further try at all (the node as if paused).
  bool pause(double seconds) {
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    while (gate_closed_) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return true;
  }

  // Job 1's molds computed by node-a, then its batch nested (no outage): batch 1, queued for cutter-1.
  void compute_and_nest() {
    auto claimed = store_->claim("compute-1");
    ASSERT_TRUE(claimed.ok() && claimed->has_value()) << claimed.error();
    std::get<std::unique_ptr<daemon::MoldsClaim>>(**claimed)->finish(computed_molds());
    claimed = store_->claim("compute-1");
    ASSERT_TRUE(claimed.ok() && claimed->has_value()) << claimed.error();
    auto& nest = std::get<std::unique_ptr<daemon::NestClaim>>(**claimed);
    ASSERT_TRUE(write_file_durably(nest->work().batch_dir / "cut.hpgl", "IN;\n").ok());
    nest->finish(nested_job_1());
    ASSERT_EQ(query("SELECT state FROM batches WHERE id = 1"), "queued");
  }

  static daemon::JobMolds computed_molds() {
    daemon::JobMolds made;
    made.verdict = daemon::JobMolds::Verdict::Computed;
    made.molds = 2;
    made.pieces = 2;
    made.report = nlohmann::json::object();
    return made;
  }
  static daemon::NestResult nested_job_1() {
    daemon::NestResult nested;
    nested.placed = {"1"};
    nested.cut_file = "cut.hpgl";
    nested.pieces = 2;
    nested.utilisation = 0.5;
    return nested;
  }

  // Runs `finish` while the server is stopped for `outage_s`; the seconds it took after the restart.
  double finish_through_an_outage(double outage_s, const std::function<void()>& finish) {
    EXPECT_TRUE(server_.stop().empty());
    std::atomic<bool> finished{false};
    std::thread worker([&] {
      finish();
      finished = true;
    });
    std::this_thread::sleep_for(std::chrono::duration<double>(outage_s));
    EXPECT_FALSE(finished.load()) << "finished while the ledger was away";
    EXPECT_TRUE(server_.start().empty());
    const auto back = Clock::now();
    worker.join();
    return seconds_since(back);
  }

  int events(const std::string& event) {
    return std::stoi(query("SELECT count(*) FROM job_events WHERE event = '" + event + "'"));
  }

  std::filesystem::path shared_root_;
  std::unique_ptr<daemon::SharedStore> shared_;
  daemon::LedgerConfig ledger_;
  std::shared_ptr<const daemon::DaemonConfig> settings_;
  std::unique_ptr<ledger::LedgerClient> entering_;
  daemon::LedgerJournal journal_{nullptr};
  std::unique_ptr<ledger::LeaseKeeper> keeper_;
  std::unique_ptr<daemon::LedgerComputeStore> store_;
  std::atomic<bool> gate_closed_{false};
  // Scaled down from the defaults by five; FinishedWorkAtTheDefaultLeaseTest uses the defaults.
  double lease_s_ = 6, heartbeat_s_ = 0.5;
};

// The shipped defaults: lease 30 s, heartbeat 5 s.
class FinishedWorkAtTheDefaultLeaseTest : public FinishedWorkOutageTest {
 protected:
  FinishedWorkAtTheDefaultLeaseTest() {
    lease_s_ = 30;
    heartbeat_s_ = 5;
  }
};

TEST_F(FinishedWorkAtTheDefaultLeaseTest, MoldsAndANestingFinishedWhileTheLedgerIsAway10sAreWrittenWhenItIsBack) {
  constexpr double kOutage_s = 10;
  auto claimed = store_->claim("compute-1");
  ASSERT_TRUE(claimed.ok()) << claimed.error();
  ASSERT_TRUE(claimed->has_value());
  auto& molds = std::get<std::unique_ptr<daemon::MoldsClaim>>(**claimed);
  const double molds_after_s = finish_through_an_outage(kOutage_s, [&] { molds->finish(computed_molds()); });
  EXPECT_LT(molds_after_s, 2.0) << "written by its node, not after its lease ran out";
  EXPECT_EQ(query("SELECT state FROM jobs WHERE id = 1"), "computed");
  EXPECT_EQ(events("claimed"), 1);
  EXPECT_EQ(events("computed"), 1);

  claimed = store_->claim("compute-1");
  ASSERT_TRUE(claimed.ok()) << claimed.error();
  ASSERT_TRUE(claimed->has_value());
  auto& nest = std::get<std::unique_ptr<daemon::NestClaim>>(**claimed);
  ASSERT_TRUE(write_file_durably(nest->work().batch_dir / "cut.hpgl", "IN;\n").ok());
  const double nest_after_s = finish_through_an_outage(kOutage_s, [&] { nest->finish(nested_job_1()); });
  EXPECT_LT(nest_after_s, 2.0);
  EXPECT_EQ(query("SELECT state FROM batches"), "queued");
  EXPECT_EQ(query("SELECT cut_file FROM batches"), "batches/1/cut.hpgl");
  EXPECT_TRUE(std::filesystem::exists(shared_root_ / "batches" / "1" / "cut.hpgl"));
  EXPECT_EQ(events("batched"), 1);
  EXPECT_EQ(events("nested"), 1);
  EXPECT_EQ(events("regrouped") + events("requeued"), 0);
}

TEST_F(FinishedWorkAtTheDefaultLeaseTest, ACutThroughA25sOutageIsMarkedCutAndNothingIsHeld) {
  // The server away 25 s (and its restart) of the 30 s lease while the cutter cuts, node-b
  // sweeping as soon as it is back.
  ASSERT_TRUE(entering_->register_node({"compute", "station"}, {"cutter-1"}, 3).ok());
  ASSERT_NO_FATAL_FAILURE(compute_and_nest());
  daemon::LedgerCutStore cutter("cutter-1", ledger_, *shared_, *keeper_, [this](double s) { return pause(s); }, journal_);
  auto order = cutter.claim();
  ASSERT_TRUE(order.ok() && order->has_value()) << order.error();
  ASSERT_TRUE(cutter.mark_sending(**order).ok());
  ASSERT_TRUE(server_.stop().empty());
  std::this_thread::sleep_for(std::chrono::seconds(25));  // the cutter cuts meanwhile
  ASSERT_TRUE(server_.start().empty());
  auto sweeper = client("node-b");
  ASSERT_TRUE(sweeper);
  std::vector<long long> held;
  // node-b sweeps through the next heartbeats after the restart, as every node does.
  const auto sweep_until = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                              std::chrono::duration<double>(1.5 * heartbeat_s_));
  while (Clock::now() < sweep_until) {
    auto swept = sweeper->sweep_expired(3, heartbeat_s_);
    if (swept) held.insert(held.end(), swept->batches_held.begin(), swept->batches_held.end());
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_TRUE(held.empty()) << "the station was alive all along";
  EXPECT_EQ(cutter.record_end(**order, daemon::CutEnd::Cut, "", {}), daemon::CutEnd::Cut);
  EXPECT_EQ(query("SELECT state FROM batches WHERE id = 1"), "cut");
  EXPECT_EQ(query("SELECT state FROM jobs WHERE id = 1"), "done");
  EXPECT_EQ(events("held"), 0);
  EXPECT_EQ(events("cut"), 1);
}

TEST_F(FinishedWorkOutageTest, MoldsFinishedAfterTheirLeaseWasTakenOverAreRefusedAndComputedOnce) {
  // The server away longer than the lease: node-b's sweep takes the job back and node-b claims it
  // before node-a's late result reaches the ledger (the gate holds node-a's retries meanwhile).
  auto claimed = store_->claim("compute-1");
  ASSERT_TRUE(claimed.ok() && claimed->has_value()) << claimed.error();
  auto& molds = std::get<std::unique_ptr<daemon::MoldsClaim>>(**claimed);
  gate_closed_ = true;
  ASSERT_TRUE(server_.stop().empty());
  std::thread late([&] { molds->finish(computed_molds()); });
  // However this test ends, the late result is let through and its thread joined (a failed ASSERT
  // below must not leave a joinable thread behind: that terminates the whole test binary).
  struct JoinLate {
    std::thread& thread;
    std::atomic<bool>& gate_closed;
    ~JoinLate() {
      gate_closed = false;
      if (thread.joinable()) thread.join();
    }
  } join_late{late, gate_closed_};
  std::this_thread::sleep_for(std::chrono::duration<double>(lease_s_ + 2 * heartbeat_s_));
  ASSERT_TRUE(server_.start().empty());
  auto other = client("node-b");
  ASSERT_TRUE(other);
  // node-b sweeps at its heartbeats, as every node does. One sweep may find the lease row locked by
  // node-a's keeper, whose renewal after the outage is being refused at that moment (the sweep skips
  // locked rows): the next sweep takes it.
  std::vector<long long> requeued;
  const auto sweep_until = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(4 * heartbeat_s_));
  while (requeued.empty() && Clock::now() < sweep_until) {
    auto swept = other->sweep_expired(3, heartbeat_s_);
    ASSERT_TRUE(swept.ok()) << swept.error();
    requeued = swept->jobs_requeued;
    if (requeued.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(requeued, std::vector<long long>{1});
  auto taken = other->claim_job(lease_s_);
  ASSERT_TRUE(taken.ok() && taken->has_value()) << taken.error();
  gate_closed_ = false;
  late.join();
  EXPECT_EQ(query("SELECT state FROM jobs WHERE id = 1"), "computing") << "node-a's late result was refused";
  ASSERT_TRUE(other->mark_computed((*taken)->lease, 2).ok());
  EXPECT_EQ(events("computed"), 1);
  EXPECT_EQ(events("claimed"), 2);
}

TEST_F(FinishedWorkOutageTest, TheSweepRemovesOldBatchFoldersNoRowUsesAndKeepsTheRest) {
  {
    pqxx::connection connection(url_);
    pqxx::work tx(connection);
    tx.exec("INSERT INTO batches (id, cutter, material, state, created_by) VALUES"
            " (1, 'cutter-1', 'calf', 'queued', 'node-a'), (2, 'cutter-1', 'calf', 'dissolved', 'node-a'),"
            " (3, 'cutter-1', 'calf', 'nesting', 'node-a')");
    tx.commit();
  }
  // 1 queued, 2 dissolved (a refused late nesting), 3 still nesting, 4 no row at all, and a
  // scratch folder of a nesting in progress.
  for (const std::string name : {"1", "2", "3", "4", "5.part-node-b-77-1"}) {
    std::filesystem::create_directories(shared_root_ / "batches" / name);
    ASSERT_TRUE(write_file_durably(shared_root_ / "batches" / name / "cut.hpgl", "IN;\n").ok());
  }
  auto sweeper = client("node-b");
  ASSERT_TRUE(sweeper);
  auto removed = daemon::remove_orphan_batch_folders(*sweeper, *shared_, 60);
  ASSERT_TRUE(removed.ok()) << removed.error();
  EXPECT_TRUE(removed->empty()) << "younger than the grace period";
  daemon::testing::LogLines log;
  removed = daemon::remove_orphan_batch_folders(*sweeper, *shared_, 0);
  ASSERT_TRUE(removed.ok()) << removed.error();
  EXPECT_EQ(*removed, (std::vector<std::string>{"2", "4"}));
  EXPECT_EQ(log.count("removed: no batch in the ledger uses it"), 2) << log.text();
  for (const std::string kept : {"1", "3", "5.part-node-b-77-1"})
    EXPECT_TRUE(std::filesystem::exists(shared_root_ / "batches" / kept)) << kept;
  for (const std::string gone : {"2", "4"}) EXPECT_FALSE(std::filesystem::exists(shared_root_ / "batches" / gone)) << gone;
}

}  // namespace
}  // namespace lastcut::test
