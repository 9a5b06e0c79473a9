// `lastcut status` and `lastcut requeue` on a node configured with [ledger]: the real binary reads
// and writes the shared ledger of a real server (jobs put there by ledger clients).
#include <algorithm>
#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/ledger/ledger_fixture.hpp"
#include "tests/support/lastcut_cli.hpp"

namespace lastcut::test {
namespace {

class CliStatusTest : public LedgerTest {
 protected:
  void SetUp() override {
    LedgerTest::SetUp();
    if (HasFatalFailure()) return;
    config_ = server_.folder() / "lastcut.toml";
    std::ofstream(config_) << "[paths]\nwatch = \"in\"\nspool = \"spool\"\nmachines = \"machines\"\n"
                              "[jobs]\ndefault_material = \"calf\"\ndefault_cutter = \"cutter-1\"\n"
                              "[materials.calf]\nwidth_mm = 500\nlength_mm = 900\n"
                              "[cutters.cutter-1]\nprotocol = \"grbl\"\nport = \"/dev/null\"\nmachine = \"m\"\n"
                              "[ledger]\nurl = \""
                           << url_ << "\"\nnode = \"office\"\nroles = [\"compute\"]\nshared_dir = \"shared\"\n";
    // The shop: station-1 owns cutter-1; job 1 cut, job 2 held after station-1 vanished mid-send, job 3 ready.
    auto compute = client("compute-1");
    auto station = client("station-1");
    ASSERT_TRUE(compute && station);
    ASSERT_TRUE(station->register_node({"station"}, {"cutter-1"}, 3).ok());
    for (int n : {1, 2}) {
      ASSERT_TRUE(compute->enqueue(scan(n)).ok());
      auto claim = compute->claim_job(30);
      ASSERT_TRUE(claim.ok() && claim->has_value());
      ASSERT_TRUE(compute->mark_computed((*claim)->lease).ok());
      ASSERT_TRUE(nest_batch(*compute, 1).has_value());
      auto batch = station->claim_batch(30);
      ASSERT_TRUE(batch.ok() && batch->has_value());
      ASSERT_TRUE(station->mark_sending((*batch)->lease).ok());
      if (n == 1) ASSERT_TRUE(station->mark_cut((*batch)->lease).ok());
      else ASSERT_TRUE(station->hold_batch((*batch)->lease, "link lost while sending").ok());
    }
    ASSERT_TRUE(compute->enqueue(scan(3)).ok());
  }

  CommandRun lastcut(const std::string& arguments) {
    return run_lastcut(arguments + " --config '" + config_.string() + "'", server_.folder());
  }

  std::filesystem::path config_;
};

TEST_F(CliStatusTest, StatusShowsTheWholeShopFromAnyNode) {
  const CommandRun run = lastcut("status --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto status = nlohmann::json::parse(run.out);
  EXPECT_EQ(status["ledger"], url_);
  EXPECT_EQ(status["jobs"], (nlohmann::json{{"done", 1}, {"held", 1}, {"ready", 1}}));
  ASSERT_EQ(status["cutters"].size(), 1u);
  EXPECT_EQ(status["cutters"][0]["station"], "station-1");
  ASSERT_EQ(status["held"].size(), 1u);
  EXPECT_EQ(status["held"][0]["scan"], "scan-2.stl");
  EXPECT_EQ(status["held"][0]["reason"], "link lost while sending");
  EXPECT_EQ(status["recent"].size(), 3u);

  const CommandRun text = lastcut("status");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_EQ(text.out.rfind("ledger " + url_ + ": 1 done, 1 held, 1 ready\n", 0), 0u) << text.out;
  EXPECT_NE(text.out.find("  cutter cutter-1       at station-1, 0 batch(es) queued\n"), std::string::npos) << text.out;
}

TEST_F(CliStatusTest, RequeueHandsAHeldJobBackAndRefusesOthers) {
  const std::string held = query("SELECT id FROM jobs WHERE state = 'held'");
  const CommandRun requeued = lastcut("requeue " + held);
  EXPECT_EQ(requeued.exit_code, 0) << requeued.err;
  EXPECT_EQ(requeued.out, "job " + held + " is back in the ledger's queue; a compute node takes it up\n");
  EXPECT_EQ(query("SELECT state FROM jobs WHERE id = " + held), "ready");
  EXPECT_EQ(query("SELECT node || ' ' || detail FROM job_events WHERE event = 'requeued'"),
            "office by the operator (was held)");

  const CommandRun again = lastcut("requeue " + held);
  EXPECT_EQ(again.exit_code, 1);
  EXPECT_EQ(again.err, "lastcut requeue: job " + held + " is ready, neither held nor failed: nothing to requeue\n");
  const CommandRun bad = lastcut("requeue 20261121-235012-001");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err,
            "lastcut requeue: \"20261121-235012-001\" is not a ledger job id (a whole number, see lastcut status)\n");
}

TEST_F(CliStatusTest, UnreachableLedgerIsOneLine) {
  ASSERT_TRUE(server_.stop().empty());
  const CommandRun run = lastcut("status");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err.rfind("lastcut status: ledger unreachable while connecting to " + url_ + ": ", 0), 0u) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1);
}

}  // namespace
}  // namespace lastcut::test
