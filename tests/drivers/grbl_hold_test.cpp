// Feed hold, resume and soft reset against the real grbl simulator over a pty, through
// GrblSession: resume is sent only from a completed hold (Hold:0), never from Run or Idle.
#include <gtest/gtest.h>

#include "drivers/grbl/grbl_session.hpp"
#include "drivers/transport/transport.hpp"
#include "tests/drivers/sim_process.hpp"

namespace lastcut::drivers::grbl {
namespace {

TEST(GrblHold, HoldStopsResumeContinuesAndResetAfterHoldKeepsPosition) {
  testing::TempDir dir;
  testing::SimProcess sim({"grbl", "--link", dir / "grbl", "--time-scale", "1"});
  ASSERT_TRUE(sim.ready()) << sim.ready_line();
  CutterConfig config;
  config.timeout_s = 3;
  OpenResult opened = open_transport(dir / "grbl", {}, 1);
  ASSERT_TRUE(opened.transport) << opened.error;
  std::vector<std::string> log;
  GrblSession session(*opened.transport, config, log);
  ASSERT_TRUE(session.connect().ok);

  const StepResult not_held = session.resume();
  EXPECT_FALSE(not_held.ok);
  EXPECT_NE(not_held.error.find("not a completed hold"), std::string::npos) << not_held.error;

  ASSERT_TRUE(session.send_and_wait("G1 X500 F600").ok);  // 50 s of motion
  Reply status;
  ASSERT_TRUE(session.query_status(status, 2).ok);
  EXPECT_EQ(session.state(), "Run");
  const StepResult refused_in_run = session.resume();
  EXPECT_FALSE(refused_in_run.ok) << "cycle start while running must not be sent";

  ASSERT_TRUE(session.feed_hold().ok);
  EXPECT_EQ(session.state(), "Hold:0");
  ASSERT_TRUE(session.resume().ok);
  ASSERT_TRUE(session.query_status(status, 2).ok);
  EXPECT_EQ(session.state(), "Run");

  // Reset from a completed hold: no alarm (position kept); reset in motion would raise ALARM:3.
  ASSERT_TRUE(session.feed_hold().ok);
  ASSERT_TRUE(session.soft_reset().ok);
  ASSERT_TRUE(session.query_status(status, 2).ok);
  EXPECT_EQ(session.state(), "Idle");

  ASSERT_TRUE(session.send_and_wait("G1 X300 F600").ok);  // moving again
  ASSERT_TRUE(session.soft_reset().ok);
  ASSERT_TRUE(session.query_status(status, 2).ok);
  EXPECT_EQ(session.state(), "Alarm");
  bool alarm_logged = false;
  for (const auto& line : log) alarm_logged |= line.find("ALARM:3") != std::string::npos;
  EXPECT_TRUE(alarm_logged);
}

}  // namespace
}  // namespace lastcut::drivers::grbl
