// Finished work waits for a ledger that is away (daemon/ledger_node/ledger_journal.hpp
// change_once_reachable): computed molds and a nested batch finished while the real PostgreSQL
// server is stopped are written as soon as it is back, by the node that made them, without
// waiting for a lease to run out; nothing is computed or nested twice (the ledger's events).
// Scaled down from the defaults: lease 6 s, heartbeat 0.5 s, the server away 3 s. And the sweep of
// batch folders no row uses any more (daemon/ledger_node/orphan_sweep.hpp).
#include <atomic>
#include <chrono>
#include <thread>

#include "daemon/job/job_ticket.hpp"
#include "daemon/ledger/lease_keeper.hpp"
#include "daemon/ledger_node/ledger_compute_store.hpp"
#include "daemon/ledger_node/ledger_journal.hpp"
#include "daemon/ledger_node/orphan_sweep.hpp"
#include "engine/core/durable_file.hpp"
#include "tests/ledger/ledger_fixture.hpp"

namespace lastcut::test {
namespace {

constexpr double kLease_s = 6, kHeartbeat_s = 0.5, kOutage_s = 3;

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
    ledger_.lease_s = kLease_s;
    ledger_.heartbeat_s = kHeartbeat_s;
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
    keeper_ = std::make_unique<ledger::LeaseKeeper>(url_, "node-a", kLease_s, kHeartbeat_s, [](const std::string&) {});
    store_ = std::make_unique<daemon::LedgerComputeStore>(
        ledger_, *shared_, *keeper_, [this] { return settings_; }, journal_, [](double seconds) {
          std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
          return true;
        });
  }

  // Runs `finish` while the server is stopped for kOutage_s; the seconds it took after the restart.
  double finish_through_an_outage(const std::function<void()>& finish) {
    EXPECT_TRUE(server_.stop().empty());
    std::atomic<bool> finished{false};
    std::thread worker([&] {
      finish();
      finished = true;
    });
    std::this_thread::sleep_for(std::chrono::duration<double>(kOutage_s));
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
};

TEST_F(FinishedWorkOutageTest, MoldsAndANestingFinishedWhileTheLedgerIsAwayAreWrittenWhenItIsBack) {
  auto claimed = store_->claim("compute-1");
  ASSERT_TRUE(claimed.ok()) << claimed.error();
  ASSERT_TRUE(claimed->has_value());
  auto& molds = std::get<std::unique_ptr<daemon::MoldsClaim>>(**claimed);
  daemon::JobMolds made;
  made.verdict = daemon::JobMolds::Verdict::Computed;
  made.molds = 2;
  made.pieces = 2;
  made.report = nlohmann::json::object();
  const double molds_after_s = finish_through_an_outage([&] { molds->finish(made); });
  EXPECT_LT(molds_after_s, kLease_s / 2) << "written by its node, not after its lease ran out";
  EXPECT_EQ(query("SELECT state FROM jobs WHERE id = 1"), "computed");
  EXPECT_EQ(events("claimed"), 1);
  EXPECT_EQ(events("computed"), 1);

  claimed = store_->claim("compute-1");
  ASSERT_TRUE(claimed.ok()) << claimed.error();
  ASSERT_TRUE(claimed->has_value());
  auto& nest = std::get<std::unique_ptr<daemon::NestClaim>>(**claimed);
  ASSERT_TRUE(write_file_durably(nest->work().batch_dir / "cut.hpgl", "IN;\n").ok());
  daemon::NestResult nested;
  nested.placed = {"1"};
  nested.cut_file = "cut.hpgl";
  nested.pieces = 2;
  nested.utilisation = 0.5;
  const double nest_after_s = finish_through_an_outage([&] { nest->finish(nested); });
  EXPECT_LT(nest_after_s, kLease_s / 2);
  EXPECT_EQ(query("SELECT state FROM batches"), "queued");
  EXPECT_EQ(query("SELECT cut_file FROM batches"), "batches/1/cut.hpgl");
  EXPECT_TRUE(std::filesystem::exists(shared_root_ / "batches" / "1" / "cut.hpgl"));
  EXPECT_EQ(events("batched"), 1);
  EXPECT_EQ(events("nested"), 1);
  EXPECT_EQ(events("regrouped") + events("requeued"), 0);
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
  removed = daemon::remove_orphan_batch_folders(*sweeper, *shared_, 0);
  ASSERT_TRUE(removed.ok()) << removed.error();
  EXPECT_EQ(*removed, (std::vector<std::string>{"2", "4"}));
  for (const std::string kept : {"1", "3", "5.part-node-b-77-1"})
    EXPECT_TRUE(std::filesystem::exists(shared_root_ / "batches" / kept)) << kept;
  for (const std::string gone : {"2", "4"}) EXPECT_FALSE(std::filesystem::exists(shared_root_ / "batches" / gone)) << gone;
}

}  // namespace
}  // namespace lastcut::test
