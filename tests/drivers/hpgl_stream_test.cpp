// HP-GL streaming over REAL pseudo-terminals and loopback TCP against `lastcut-sim hpgl`:
// XON/XOFF and ESC.B flow control keep a small buffer from overflowing, the cut is recorded
// byte-exact, completion is confirmed with OA, and faults end cleanly within the timeout.
#include <gtest/gtest.h>

#include <algorithm>

#include "drivers/cutter.hpp"
#include "drivers/hpgl/hpgl_status.hpp"
#include "tests/drivers/sim_process.hpp"
#include "tests/drivers/stream_checks.hpp"

namespace lastcut::drivers {
namespace {

using testing::SimProcess;
using testing::TempDir;
using testing::read_file;
using testing::expect_interrupted;
using testing::stat_value;
using testing::timed_send;

std::string make_hpgl(int segments) {
  std::string program = "IN;SP1;PU0,0;\n";
  for (int i = 0; i < segments; ++i) {
    program += "PD" + std::to_string(400 + (i * 37) % 4000) + "," + std::to_string(200 + (i * 91) % 3000) + ";\n";
  }
  program += "PU0,0;SP0;\n";
  return program;
}

struct HpglFixture : testing::SimulatedCutter {
  explicit HpglFixture(const std::string& handshake, std::vector<std::string> extra = {}) {
    std::vector<std::string> args{"hpgl", "--link", dir / "plotter", "--record", dir / "rec", "--handshake", handshake,
                                  "--buffer", "256", "--baud", "38400"};
    args.insert(args.end(), extra.begin(), extra.end());
    if (std::find(extra.begin(), extra.end(), "--speed") == extra.end()) args.insert(args.end(), {"--speed", "2000"});
    sim = std::make_unique<SimProcess>(args);
    config.name = "test-plotter";
    config.protocol = "hpgl";
    config.port = dir / "plotter";
    config.baud = 38400;
    config.flow = handshake == "xonxoff" ? "xonxoff" : "none";
    config.hpgl_handshake = handshake == "escb" ? "escb" : "";
    config.timeout_s = 2;
    received_file = "hpgl-received.hpgl";
    stats_file = "hpgl-stats.json";
  }
};

TEST(HpglStream, XonXoffKeepsTheSmallBufferFromOverflowing) {
  HpglFixture f("xonxoff");
  ASSERT_TRUE(f.sim->ready()) << f.sim->ready_line();
  const std::string stats = f.deliver(make_hpgl(150));
  EXPECT_EQ(stat_value(stats, "overflows"), 0);
  EXPECT_GT(stat_value(stats, "xoff_sent"), 0) << "the cutter must have been slower than the line for this test to mean anything";
  EXPECT_LE(stat_value(stats, "buffer_high_water_bytes"), 256);
  const std::string svg = read_file(f.dir.path() / "rec" / "cut.svg");
  EXPECT_NE(svg.find("<line"), std::string::npos);
}

// PD instructions of ~150 bytes in a 256-byte buffer: XOFF comes at 192 bytes with the next instruction
// ~40 bytes in, and at most two 16-byte chunks follow it; once the one before is plotted the buffer
// holds ~75 bytes of an unfinished PD, above the 64 at which XON comes. The plotter must not wait for
// bytes it has stopped itself.
TEST(HpglStream, XonXoffWithInstructionsLongerThanAQuarterOfTheBuffer) {
  HpglFixture f("xonxoff", {"--speed", "1000"});
  ASSERT_TRUE(f.sim->ready()) << f.sim->ready_line();
  std::string program = "IN;SP1;PU0,0;\n";
  for (int i = 0; i < 12; ++i) {
    program += "PD";
    for (int k = 0; k < 14; ++k) program += (k ? "," : "") + std::to_string(1000 + (i * 37 + k * 211) % 3000) + "," + std::to_string(1000 + (k * 97) % 2000);
    program += ";\n";
  }
  program += "PU0,0;SP0;\n";
  const std::string stats = f.deliver(program);
  EXPECT_EQ(stat_value(stats, "overflows"), 0);
  EXPECT_GT(stat_value(stats, "xoff_sent"), 0) << "the plotter must have been slower than the line for this test to mean anything";
}

TEST(HpglStream, EscBHandshakeSendsOnlyWhatFits) {
  HpglFixture f("escb");
  ASSERT_TRUE(f.sim->ready());
  const std::string stats = f.deliver(make_hpgl(150));
  EXPECT_EQ(stat_value(stats, "overflows"), 0);
  EXPECT_GT(stat_value(stats, "buffer_high_water_bytes"), 128) << "ESC.B should let the buffer fill";
}

TEST(HpglStream, WithoutFlowControlASlowCutterOverflowsAndSaysSo) {
  // The same job with flow control off: the simulator really loses bytes, and ESC.E reports it.
  HpglFixture f("none", {"--speed", "100"});
  ASSERT_TRUE(f.sim->ready());
  const SendResult result = f.send(make_hpgl(150));
  EXPECT_NE(result.outcome, SendOutcome::Done);
  EXPECT_NE(result.reason.find("overflow"), std::string::npos) << result.reason;
  const auto [received, stats] = f.record();
  EXPECT_GT(stat_value(stats, "overflows"), 0);
}

// A fault injected into the plotter ends the job as Interrupted with the reason in words.
void expect_fault_interrupts(const std::string& handshake, const std::string& fault,
                             std::initializer_list<const char*> reason) {
  HpglFixture f(handshake, {"--fault", fault});
  ASSERT_TRUE(f.sim->ready());
  expect_interrupted(f.send(make_hpgl(150)), reason);
}

TEST(HpglStream, DeviceErrorInterrupts) {
  expect_fault_interrupts("escb", "error-at-line=40:13", {"device error 13", "nothing was resent"});
}

TEST(HpglStream, GarbageAnswerInterrupts) { expect_fault_interrupts("escb", "garbage-at-line=30", {"unintelligible"}); }

TEST(HpglStream, DroppedLinkInterrupts) { expect_fault_interrupts("xonxoff", "drop-at-line=30", {"lost"}); }

TEST(HpglStream, StalledCutterInterruptsWithinTheTimeout) {
  HpglFixture f("escb", {"--fault", "stall-at-line=30"});
  ASSERT_TRUE(f.sim->ready());
  const auto [result, elapsed_s] = timed_send(f.config, make_hpgl(150));
  expect_interrupted(result, {"no answer"});
  EXPECT_LT(elapsed_s, f.config.timeout_s + 2);
}

TEST(HpglStream, XoffHeldForeverInterruptsWithinTheTimeout) {
  // A slow cutter (20 mm/s) fills its buffer and sends XOFF at once (the first cut takes 0.5 s),
  // then freezes at instruction 6 without ever sending XON.
  HpglFixture f("xonxoff", {"--fault", "stall-at-line=6", "--speed", "20"});
  ASSERT_TRUE(f.sim->ready());
  f.config.timeout_s = 0.2;  // XOFF may last 10 x timeout_s = 2 s
  expect_interrupted(f.send(make_hpgl(400)), {"XOFF"});
}

TEST(HpglStream, OverLoopbackTcp) {
  CutterConfig config;
  config.hpgl_handshake = "escb";
  config.timeout_s = 2;
  testing::expect_delivered_over_loopback("hpgl", {"--handshake", "escb", "--baud", "0", "--time-scale", "0"}, config,
                                          make_hpgl(300), "hpgl-received.hpgl");
}

TEST(HpglStatus, ExplainsDeviceAndInstructionErrors) {
  EXPECT_NE(hpgl::device_error_meaning(16).find("overflow"), std::string::npos);
  EXPECT_NE(hpgl::device_error_meaning(15).find("baud"), std::string::npos);
  EXPECT_NE(hpgl::hpgl_error_meaning(1).find("not recognized"), std::string::npos);
}

}  // namespace
}  // namespace lastcut::drivers
