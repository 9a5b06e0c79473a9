// lastcut's grbl driver against the REAL grbl 1.1h firmware (gnea/grbl with its host simulator,
// from ../shared/peers/grbl, built by build_grbl_sim.sh) over a pseudo-terminal: the checks the
// project's own simulator passes in tests/drivers (long jobs, a bad line mid-job, feed hold and
// resume, an alarm, a soft reset, the link lost), here with a peer no one here wrote. The
// firmware's block log (one line per planner block) is the count of what it executed.
#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <sstream>
#include <thread>

#include "drivers/cutter.hpp"
#include "drivers/grbl/grbl_session.hpp"
#include "drivers/transport/transport.hpp"
#include "tests/drivers/sim_process.hpp"
#include "tests/drivers/stream_checks.hpp"
#include "tests/peers/firmware_peer.hpp"

namespace lastcut::drivers {
namespace {

using testing::expect_interrupted;
using testing::SimProcess;
using testing::TempDir;
using testing::Firmware;
using testing::moves;
using testing::motion_lines;
using testing::tail_of;

TEST(GrblFirmware, ABadLineAtFiveHundredStopsTheJobWithinSixtyBlocks) {
  Firmware firmware;
  ASSERT_TRUE(firmware.process->ready()) << firmware.process->ready_line();
  std::string program = moves(1000);
  // Replace line 500 (1-based) by a command grbl does not know.
  std::size_t at = 0;
  for (int line = 1; line < 500; ++line) at = program.find('\n', at) + 1;
  const int motion_before = motion_lines(program.substr(0, at));
  program.replace(at, program.find('\n', at) - at, "G999");
  expect_interrupted(firmware.send(program), {"error:20", "line 500", "nothing was resent"});
  const int executed = static_cast<int>(firmware.blocks().size());
  EXPECT_GE(executed, motion_before) << "every line before the bad one must have run";
  EXPECT_LE(executed - motion_before, 60) << "the job went on for " << executed - motion_before << " blocks";

  const SendResult next = firmware.send(moves(20));  // the machine is usable again
  EXPECT_EQ(next.outcome, SendOutcome::Done) << next.reason;
}

// The same sequence as tests/drivers/grbl_hold_test.cpp on lastcut-sim: resume only from a
// completed hold, reset after a hold keeps the position, reset in motion raises ALARM:3.
TEST(GrblFirmware, FeedHoldResumeAndSoftResetBehaveAsOurSimulatorSays) {
  Firmware firmware;
  ASSERT_TRUE(firmware.process->ready()) << firmware.process->ready_line();
  firmware.config.timeout_s = 5;
  OpenResult opened = open_transport(firmware.config.port, {}, 1);
  ASSERT_TRUE(opened.transport) << opened.error;
  std::vector<std::string> log;
  grbl::GrblSession session(*opened.transport, firmware.config, log);
  ASSERT_TRUE(session.connect().ok);

  EXPECT_FALSE(session.resume().ok) << "cycle start outside a completed hold must not be sent";
  ASSERT_TRUE(session.send_and_wait("G1 X200 F400").ok);  // 30 s of motion
  // The "ok" comes when the line is planned; the firmware starts the cycle on a later main-loop pass.
  grbl::Reply status;
  for (int i = 0; i < 50 && session.state() != "Run"; ++i) ASSERT_TRUE(session.query_status(status, 5).ok);
  EXPECT_EQ(session.state(), "Run");
  EXPECT_FALSE(session.resume().ok) << "cycle start while running must not be sent";

  ASSERT_TRUE(session.feed_hold().ok);
  EXPECT_EQ(session.state(), "Hold:0");
  ASSERT_TRUE(session.query_status(status, 5).ok);
  const auto held_at = status.position;
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_TRUE(session.query_status(status, 5).ok);
  EXPECT_EQ(status.position, held_at) << "a completed hold must not move";
  ASSERT_TRUE(session.resume().ok);
  // The firmware leaves the hold on its next main-loop pass: a report or two may still say Hold:0.
  for (int i = 0; i < 50 && session.state() != "Run"; ++i) ASSERT_TRUE(session.query_status(status, 5).ok);
  EXPECT_EQ(session.state(), "Run");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_TRUE(session.query_status(status, 5).ok);
  EXPECT_NE(status.position, held_at) << "resume must move on";

  ASSERT_TRUE(session.feed_hold().ok);
  ASSERT_TRUE(session.soft_reset().ok);
  ASSERT_TRUE(session.query_status(status, 5).ok);
  EXPECT_EQ(session.state(), "Idle") << "a reset from a completed hold keeps the position: no alarm";

  ASSERT_TRUE(session.send_and_wait("G1 X0 F400").ok);  // moving again, once the firmware has started the cycle
  for (int i = 0; i < 50 && session.state() != "Run"; ++i) ASSERT_TRUE(session.query_status(status, 5).ok);
  ASSERT_EQ(session.state(), "Run");
  ASSERT_TRUE(session.soft_reset().ok);
  ASSERT_TRUE(session.query_status(status, 5).ok);
  EXPECT_EQ(session.state(), "Alarm");
  bool alarm_logged = false;
  for (const auto& line : log) alarm_logged |= line.find("ALARM:3") != std::string::npos;
  EXPECT_TRUE(alarm_logged);
}

// A probing move that never touches anything: the firmware raises a probe alarm mid-job.
TEST(GrblFirmware, AnAlarmStopsTheJobAndTheNextIsRefusedUntilUnlocked) {
  Firmware firmware;
  ASSERT_TRUE(firmware.process->ready()) << firmware.process->ready_line();
  std::string program = moves(200);
  std::size_t at = 0;
  for (int line = 1; line < 100; ++line) at = program.find('\n', at) + 1;
  program.insert(at, "G38.2 Z-5 F500\n");
  const SendResult alarmed = firmware.send(program);
  expect_interrupted(alarmed, {"ALARM:"});

  const SendResult refused = firmware.send(moves(10));
  EXPECT_EQ(refused.outcome, SendOutcome::Failed);
  EXPECT_NE(refused.reason.find("alarm"), std::string::npos) << refused.reason;

  firmware.config.grbl_unlock = "unlock";
  const SendResult unlocked = firmware.send(moves(10));
  EXPECT_EQ(unlocked.outcome, SendOutcome::Done) << unlocked.reason << tail_of(alarmed.device_log) << tail_of(unlocked.device_log);
}

TEST(GrblFirmware, CancelHoldsThenResetsAndTheMachineKeepsWorking) {
  Firmware firmware;
  ASSERT_TRUE(firmware.process->ready()) << firmware.process->ready_line();
  std::atomic<bool> cancel{false};
  std::thread canceller([&] {
    for (int i = 0; i < 600 && firmware.blocks().size() < 100; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    cancel = true;
  });
  const SendResult cancelled = firmware.send(moves(2000), &cancel);
  canceller.join();
  EXPECT_NE(cancelled.outcome, SendOutcome::Done) << cancelled.reason;
  EXPECT_NE(cancelled.reason.find("machine held and reset"), std::string::npos) << cancelled.reason;
  const std::size_t blocks_at_cancel = firmware.blocks().size();
  EXPECT_LT(blocks_at_cancel, 2000u);


  const SendResult next = firmware.send(moves(20));
  EXPECT_EQ(next.outcome, SendOutcome::Done) << next.reason << " (the reset after a hold must not leave an alarm; cancel: " << cancelled.reason << ")"
                                             << tail_of(cancelled.device_log);
}

TEST(GrblFirmware, TheLinkLostMidJobEndsInInterruptedWithinTheTimeout) {
  Firmware firmware;
  ASSERT_TRUE(firmware.process->ready()) << firmware.process->ready_line();
  firmware.config.timeout_s = 5;
  std::atomic<double> unplugged_at_s{-1};
  const auto start = std::chrono::steady_clock::now();
  const auto seconds_since_start = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::thread unplug([&] {
    for (int i = 0; i < 600 && firmware.blocks().size() < 100; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    // The cable pulled: the firmware process and its pty go away.
    std::string output;
    testing::run_command("pkill -KILL -f '" + (firmware.dir / "firmware/blocks.txt") + "'", output);
    unplugged_at_s = seconds_since_start();
  });
  const SendResult result = firmware.send(moves(3000));
  const double ended_at_s = seconds_since_start();
  unplug.join();
  expect_interrupted(result, {"lost"});
  EXPECT_LT(firmware.blocks().size(), 3000u);
  ASSERT_GE(unplugged_at_s.load(), 0.0);
  EXPECT_LT(ended_at_s - unplugged_at_s, firmware.config.timeout_s + 2) << "the loss must be noticed within the timeout";
}

}  // namespace
}  // namespace lastcut::drivers
