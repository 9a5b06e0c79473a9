// CutterWorker (daemon/station/cutter_worker.hpp), one turn() at a time without its thread: the order
// of the store's calls around the point of no return, the bytes that reach a real simulated plotter
// (`lastcut-sim hpgl` on a pty, through the real HP-GL driver), the status reports and the log lines.
// Only the store is faked, as ninja's tests swap its CommandRunner: the spool and the ledger are
// tested through the daemon (station_behaviour_test.cpp), where a broken rule shows as a late symptom;
// here each rule of the worker fails its own case when it is broken. Cutting is at most once, so the
// checks are exact: the list of calls, the bytes received, the reason an operator reads.
#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>

#include "daemon/station/cutter_worker.hpp"
#include "tests/drivers/sim_process.hpp"
#include "tests/station/log_lines.hpp"

namespace lastcut::daemon {
namespace {

using drivers::testing::SimProcess;
using drivers::testing::TempDir;
using drivers::testing::read_file;
using Calls = std::vector<std::string>;

// Records every call in order ("claim", "sending B1", "end B1 held: <reason>" with the end the worker
// asked for) and hands out `queue` one order per claim.
class FakeCutStore : public CutStore {
 public:
  std::vector<CutOrder> queue;
  Calls calls;
  bool has_work = true;
  std::string sending_error;        // mark_sending fails with this line when set
  bool cannot_requeue = false;      // NotSent comes back Held, as the spool's when it cannot write the batch back
  std::function<void()> on_claim;   // runs between the worker's probe and its send
  std::function<void()> on_next_batch;  // runs before the worker's probe

  std::optional<std::string> next_batch() override {
    calls.push_back("next_batch");
    if (on_next_batch) on_next_batch();
    if (!has_work) return std::nullopt;
    return queue.empty() ? std::string() : queue.front().batch_id;
  }
  Result<std::optional<CutOrder>> claim() override {
    calls.push_back("claim");
    if (on_claim) on_claim();
    if (queue.empty()) return std::optional<CutOrder>();
    CutOrder order = queue.front();
    queue.erase(queue.begin());
    return std::optional<CutOrder>(order);
  }
  Status mark_sending(const CutOrder& order) override {
    calls.push_back("sending " + order.batch_id);
    return sending_error.empty() ? Status::success() : Status::failure(sending_error);
  }
  CutEnd record_end(const CutOrder& order, CutEnd end, const std::string& reason,
                    const std::vector<std::string>& /*cutter_answer*/) override {
    calls.push_back("end " + order.batch_id + " " + to_string(end) + (reason.empty() ? "" : ": " + reason));
    return end == CutEnd::NotSent && cannot_requeue ? CutEnd::Held : end;
  }
};

using testing::LogLines;

// A small job: a square after pen-up moves, eleven instructions, so a fault at the third is mid-job.
const std::string kCutFile = "IN;SP1;PU0,0;\nPD400,200;\nPD1200,200;\nPD1200,900;\nPD400,900;\nPD400,200;\nPU0,0;SP0;\n";

class CutterWorkerTest : public ::testing::Test {
 protected:
  CutterWorkerTest() {
    section.link.protocol = "hpgl";
    section.link.port = dir / "plotter";
    section.link.baud = 38400;
    section.link.flow = "xonxoff";
    section.link.timeout_s = 2;
    section.retry_interval_s = 0.75;  // unlike the worker's own waits (idle 1 s, nothing queued 0.25 s)
    worker.on_status([this](const CutterStatus& status) { reports.push_back(status); });
  }

  void start_plotter(std::vector<std::string> faults = {}) {
    std::vector<std::string> args{"hpgl",        "--link",   dir / "plotter", "--record", dir / "rec",
                                  "--handshake", "xonxoff",  "--buffer",      "256",      "--time-scale", "0"};
    for (const std::string& fault : faults) args.insert(args.end(), {"--fault", fault});
    plotter = std::make_unique<SimProcess>(args);
    ASSERT_TRUE(plotter->ready()) << plotter->ready_line();
  }
  // Stops the plotter (it writes its record then) and returns every byte of the jobs it was sent.
  std::string received() {
    EXPECT_EQ(plotter->stop(), 0) << "lastcut-sim must exit cleanly on SIGTERM";
    return read_file(dir.path() / "rec" / "hpgl-received.hpgl");
  }
  // Queues batch `id` whose cut file `id`.hpgl holds `text` (no file at all when nullopt).
  void queue(const std::string& id, const std::optional<std::string>& text = kCutFile) {
    const std::string name = id + ".hpgl";
    if (text) std::ofstream(dir.path() / name, std::ios::binary) << *text;
    store.queue.push_back(CutOrder{id, dir.path() / name, name, "job-" + id, 1, 4});
  }
  std::vector<std::string> states() const {
    std::vector<std::string> result;
    for (const CutterStatus& status : reports) result.push_back(status.state);
    return result;
  }

  TempDir dir;
  FakeCutStore store;
  ProgressMonitor monitor;
  CutterSection section;
  std::vector<CutterStatus> reports;
  LogLines log;
  CutterWorker worker{"bench", store, monitor, [this] { return section; }};
  std::unique_ptr<SimProcess> plotter;
};

TEST(CutEndOf, EachSendOutcomeBecomesTheBatchStateThatKeepsCuttingAtMostOnce) {
  EXPECT_EQ(cut_end_of(drivers::SendOutcome::Done), CutEnd::Cut);
  EXPECT_EQ(cut_end_of(drivers::SendOutcome::Failed), CutEnd::NotSent);   // nothing sent: safe to queue again
  EXPECT_EQ(cut_end_of(drivers::SendOutcome::Interrupted), CutEnd::Held);  // maybe partly cut: an operator decides
}

TEST_F(CutterWorkerTest, AReadyPlotterCutsTheStoredFileOnceAndTheBatchEndsCut) {
  start_plotter();
  queue("B1");
  EXPECT_EQ(worker.turn(), 0.0) << "after a cut the next batch is asked for at once";
  EXPECT_EQ(store.calls, (Calls{"next_batch", "claim", "sending B1", "end B1 cut"}));
  EXPECT_EQ(received(), kCutFile);
  ASSERT_GE(reports.size(), 2u);
  EXPECT_EQ(reports.front().state, "sending");
  EXPECT_EQ(reports.front().batch, "B1");
  EXPECT_EQ(reports.front().bytes_total, kCutFile.size());
  EXPECT_EQ(reports.back().state, "idle");
  EXPECT_EQ(reports.back().batch, "");
  for (std::size_t i = 0; i + 1 < reports.size(); ++i) EXPECT_EQ(reports[i].state, "sending") << "report " << i;
  EXPECT_EQ(worker.condition(), "idle");
}

TEST_F(CutterWorkerTest, WhenSendingCannotBeMarkedNothingReachesThePlotter) {
  start_plotter();
  queue("B1");
  store.sending_error = "cannot write state.json: No space left on device";
  EXPECT_EQ(worker.turn(), section.retry_interval_s);
  EXPECT_EQ(store.calls, (Calls{"next_batch", "claim", "sending B1"})) << "no end: the store decides what comes next";
  EXPECT_EQ(received(), "");
  EXPECT_EQ(log.count("its state `sending` could not be written: cannot write state.json"), 1) << log.text();
}

TEST_F(CutterWorkerTest, AMissingOrEmptyCutFileIsHeldBeforeThePointOfNoReturn) {
  start_plotter();
  queue("B1", std::nullopt);
  queue("B2", "");
  EXPECT_EQ(worker.turn(), 0.0);
  EXPECT_EQ(worker.turn(), 0.0);
  EXPECT_EQ(store.calls, (Calls{"next_batch", "claim", "end B1 held: the cut file B1.hpgl is missing or empty",
                                "next_batch", "claim", "end B2 held: the cut file B2.hpgl is missing or empty"}));
  EXPECT_EQ(received(), "");
  EXPECT_EQ(states(), (Calls{"held", "held"}));
  EXPECT_EQ(reports.back().batch, "B2");
  EXPECT_EQ(reports.back().reason, "the cut file B2.hpgl is missing or empty");
}

TEST_F(CutterWorkerTest, NoBatchIsClaimedWhileThePlotterCannotTakeItAndEachChangeIsSaidOnce) {
  queue("B1");  // the plotter is switched off: nothing at its port yet
  EXPECT_EQ(worker.turn(), section.retry_interval_s);
  EXPECT_EQ(worker.turn(), section.retry_interval_s);
  EXPECT_EQ(store.calls, (Calls{"next_batch", "next_batch"}));
  ASSERT_EQ(states(), (Calls{"waiting"})) << "one report per change, not one per try";
  EXPECT_EQ(reports[0].batch, "B1") << "the status names the batch that waits";
  EXPECT_NE(reports[0].reason, "");
  EXPECT_EQ(worker.condition(), "waiting: " + reports[0].reason);
  EXPECT_EQ(log.count("cutter bench: not ready (" + reports[0].reason + ")"), 1) << log.text();

  start_plotter();  // switched on: the batch is claimed and cut
  EXPECT_EQ(worker.turn(), 0.0);
  EXPECT_EQ(store.calls, (Calls{"next_batch", "next_batch", "next_batch", "claim", "sending B1", "end B1 cut"}));
  EXPECT_EQ(states().at(1), "idle") << "ready again before the batch starts";
  EXPECT_EQ(reports.back().state, "idle");
  EXPECT_EQ(log.count("cutter bench: ready again"), 1) << log.text();
  EXPECT_EQ(received(), kCutFile);
}

TEST_F(CutterWorkerTest, APlotterThatFaultsMidJobLeavesTheBatchHeldNeverCut) {
  start_plotter({"error-at-line=3:13"});
  queue("B1");
  EXPECT_EQ(worker.turn(), 0.0);
  ASSERT_EQ(store.calls.size(), 4u) << ::testing::PrintToString(store.calls);
  EXPECT_EQ((Calls{store.calls.begin(), store.calls.begin() + 3}), (Calls{"next_batch", "claim", "sending B1"}));
  const std::string end = store.calls[3];
  const std::string prefix = "end B1 held: cutter bench stopped while cutting batch B1: ";
  const std::string suffix = "; pieces may be partly cut";
  EXPECT_EQ(end.rfind(prefix, 0), 0u) << end;
  EXPECT_TRUE(end.size() > suffix.size() && end.ends_with(suffix)) << end;
  EXPECT_NE(end.find("device error 13"), std::string::npos) << "the driver's reason, in the middle: " << end;
  EXPECT_EQ(reports.back().state, "held");
  EXPECT_EQ(reports.back().batch, "B1");
  EXPECT_EQ("end B1 held: " + reports.back().reason, end);
  EXPECT_EQ(worker.condition(), "idle");
}

// The plotter is switched off between the probe and the send: the driver refuses before the first
// byte (Failed), so the worker asks for NotSent and the batch waits for this cutter again.
TEST_F(CutterWorkerTest, APlotterGoneBeforeTheFirstByteSendsTheBatchBackToWait) {
  start_plotter();
  queue("B1");
  store.on_claim = [this] { EXPECT_EQ(plotter->stop(), 0); };
  EXPECT_EQ(worker.turn(), section.retry_interval_s);
  ASSERT_EQ(store.calls.size(), 4u) << ::testing::PrintToString(store.calls);
  EXPECT_EQ(store.calls[3].rfind("end B1 not sent: cutter 'bench': ", 0), 0u) << store.calls[3];
  EXPECT_EQ(states(), (Calls{"sending", "waiting"}));
  EXPECT_EQ(reports.back().batch, "B1");
  EXPECT_EQ("end B1 not sent: " + reports.back().reason, store.calls[3]);
  EXPECT_EQ(log.count("back in the queue"), 1) << log.text();
}

// The same refusal when the store cannot write the batch back to the queue: the batch stays out of
// it (Held), and the status says that nothing was cut, so an operator may simply queue it again.
TEST_F(CutterWorkerTest, ABatchThatCannotGoBackToTheQueueIsHeldAsRefusedBeforeCutting) {
  start_plotter();
  queue("B1");
  store.cannot_requeue = true;
  store.on_claim = [this] { EXPECT_EQ(plotter->stop(), 0); };
  EXPECT_EQ(worker.turn(), 0.0);
  ASSERT_EQ(store.calls.size(), 4u) << ::testing::PrintToString(store.calls);
  EXPECT_EQ(store.calls[3].rfind("end B1 not sent: ", 0), 0u) << store.calls[3];
  EXPECT_EQ(states(), (Calls{"sending", "held"}));
  const std::string& reason = reports.back().reason;
  EXPECT_EQ(reason.rfind("cutter bench refused batch B1 before cutting (cutter 'bench': ", 0), 0u) << reason;
  EXPECT_TRUE(reason.ends_with("), and its return to the queue could not be written")) << reason;
  EXPECT_EQ(worker.condition(), "idle");
}

TEST_F(CutterWorkerTest, WithNoWorkInTheStoreThePlotterIsNotAsked) {
  queue("B1");
  store.has_work = false;  // nothing at the port either: a probe would report the cutter waiting
  EXPECT_GT(worker.turn(), 0);
  EXPECT_EQ(store.calls, (Calls{"next_batch"}));
  EXPECT_EQ(states(), Calls{});
  EXPECT_EQ(worker.condition(), "idle");
}

TEST_F(CutterWorkerTest, APausedCutterIsNotAskedAndClaimsNothingUntilResumed) {
  start_plotter();
  queue("B1");
  CutterPauses pauses(dir.path() / "paused-cutters.json");
  worker.set_pauses(&pauses);
  ASSERT_TRUE(pauses.pause("bench", "anna"));
  EXPECT_EQ(worker.turn(), 1.0) << "paused: the idle wait";
  EXPECT_EQ(worker.turn(), 1.0);
  EXPECT_TRUE(store.calls.empty()) << "neither the store nor the plotter is asked";
  EXPECT_EQ(states(), (std::vector<std::string>{"paused"})) << "reported once";
  EXPECT_EQ(reports.back().reason, "paused by anna; its batches wait until it is resumed");
  EXPECT_EQ(worker.condition(), "paused by anna; its batches wait until it is resumed");
  EXPECT_EQ(log.count("cutter bench: paused by anna"), 1);

  ASSERT_TRUE(pauses.resume("bench", "ben"));
  EXPECT_EQ(worker.turn(), 0.0);
  EXPECT_EQ(store.calls, (Calls{"next_batch", "claim", "sending B1", "end B1 cut"}));
  EXPECT_EQ(received(), kCutFile);
  EXPECT_EQ(states().front(), "paused");
  EXPECT_EQ(states()[1], "idle") << "the resume is reported before the cut";
  EXPECT_EQ(log.count("cutter bench: resumed"), 1);
}

TEST_F(CutterWorkerTest, APauseThatComesDuringTheProbeStopsTheClaim) {
  start_plotter();
  queue("B1");
  CutterPauses pauses(dir.path() / "paused-cutters.json");
  worker.set_pauses(&pauses);
  store.on_next_batch = [&] { ASSERT_TRUE(pauses.pause("bench", "anna")); };
  EXPECT_EQ(worker.turn(), 1.0);
  EXPECT_EQ(store.calls, (Calls{"next_batch"})) << "no claim once paused";
  EXPECT_EQ(states(), (std::vector<std::string>{"paused"}));
  EXPECT_EQ(received(), "");
}

TEST(CutterPausesFile, PausesOutliveARestartAndEachRefusalIsOneLine) {
  TempDir dir;
  const auto file = dir.path() / "paused-cutters.json";
  {
    CutterPauses pauses(file);
    EXPECT_FALSE(pauses.paused_by("table-1"));
    EXPECT_EQ(pauses.resume("table-1", "anna").error(), "cutter table-1 is not paused");
    EXPECT_EQ(*pauses.pause("table-1", "anna"),
              "cutter table-1 paused: it finishes the batch on its table, if any, and starts no other until resumed");
    EXPECT_EQ(pauses.pause("table-1", "ben").error(), "cutter table-1 is already paused (by anna)");
  }
  {
    LogLines log;
    CutterPauses again(file);
    ASSERT_EQ(again.paused_by("table-1"), std::optional<std::string>("anna"));
    EXPECT_EQ(log.count("cutter table-1: paused (by anna) before this start; it takes no batch until resumed"), 1);
    EXPECT_EQ(*again.resume("table-1", "ben"),
              "cutter table-1 resumed (paused by anna, resumed by ben): its batches are cut again");
  }
  EXPECT_TRUE(CutterPauses(file).paused().empty());
  std::ofstream(file) << "{\"paused\": [1, 2";
  LogLines log;
  EXPECT_TRUE(CutterPauses(file).paused().empty());
  EXPECT_EQ(log.count(file.string() + " unreadable, no cutter is paused: "), 1);
}

}  // namespace
}  // namespace lastcut::daemon
