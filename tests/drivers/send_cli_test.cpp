// The real `lastcut send` and `lastcut ports` binaries against the real simulator over a pty:
// exit codes 0 done / 1 failed / 3 interrupted / 2 usage, plain progress lines when not on a terminal.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "drivers/cutter_settings.hpp"

#include "tests/drivers/sim_process.hpp"

namespace lastcut::drivers {
namespace {

using testing::SimProcess;
using testing::TempDir;
using testing::run_command;

std::string lastcut_binary() { return std::string(LASTCUT_BINARY_DIR) + "/bin/lastcut"; }

std::string write_program(const TempDir& dir, int lines) {
  std::string program = "G21\nG90\nG1 F2000\n";
  for (int i = 0; i < lines; ++i) program += "G1 X" + std::to_string(i % 50) + " Y" + std::to_string(i % 30) + "\n";
  const std::string path = dir / "job.nc";
  std::ofstream(path) << program;
  return path;
}

TEST(SendCli, DoneExitsZeroWithPlainProgressLines) {
  TempDir dir;
  SimProcess sim({"grbl", "--link", dir / "grbl", "--time-scale", "0", "--record", dir / "rec"});
  ASSERT_TRUE(sim.ready()) << sim.ready_line();
  std::string out;
  const int rc = run_command(lastcut_binary() + " send " + write_program(dir, 200) + " --port " + (dir / "grbl") +
                                 " --protocol grbl --timeout 3",
                             out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("done: job finished"), std::string::npos) << out;
  EXPECT_NE(out.find("progress: ["), std::string::npos) << out;
  EXPECT_EQ(out.find("\r"), std::string::npos) << "no terminal control characters in a log";
  EXPECT_EQ(sim.stop(), 0);
  EXPECT_EQ(testing::read_file(dir.path() / "rec" / "grbl-received.nc"), testing::read_file(dir / "job.nc"));
}

// `lastcut send` of a `lines`-line program with `flags` to a simulated grbl that answers error:22 at line 10.
int send_to_grbl_failing_at_line_10(const TempDir& dir, int lines, const std::string& flags, std::string& out) {
  SimProcess sim({"grbl", "--link", dir / "grbl", "--time-scale", "0", "--fault", "error-at-line=10:22"});
  EXPECT_TRUE(sim.ready()) << sim.ready_line();
  return run_command(lastcut_binary() + " send " + write_program(dir, lines) + " --port " + (dir / "grbl") +
                         " --protocol grbl --timeout 3 " + flags,
                     out);
}

TEST(SendCli, InterruptedExitsThreeAndSaysNothingIsResent) {
  TempDir dir;
  std::string out;
  const int rc = send_to_grbl_failing_at_line_10(dir, 100, "", out);
  EXPECT_EQ(rc, 3) << out;
  EXPECT_NE(out.find("INTERRUPTED"), std::string::npos) << out;
  EXPECT_NE(out.find("error:22"), std::string::npos) << out;
  EXPECT_NE(out.find("nothing was resent"), std::string::npos) << out;
}

TEST(SendCli, FailedAndUsageErrorsHaveTheirOwnExitCodes) {
  TempDir dir;
  const std::string file = write_program(dir, 5);
  std::string out;
  EXPECT_EQ(run_command(lastcut_binary() + " send " + file + " --port " + (dir / "nothing") + " --protocol grbl", out), 1) << out;
  EXPECT_NE(out.find("failed (nothing was cut)"), std::string::npos) << out;
  EXPECT_EQ(run_command(lastcut_binary() + " send " + file + " --port " + (dir / "nothing"), out), 2) << out;
  EXPECT_NE(out.find("--protocol"), std::string::npos) << out;
  EXPECT_EQ(run_command(lastcut_binary() + " send " + file, out), 2) << out;
}

TEST(SendCli, SerialFramingAndGrblOptionsReachTheLink) {
  TempDir dir;
  std::string out;
  // The interrupted job prints the device log, which names the link's framing as opened.
  const int rc = send_to_grbl_failing_at_line_10(dir, 50,
                                                 "--parity E --data-bits 7 --stop-bits 2 --streaming send-wait "
                                                 "--rx-buffer 128 --status-poll 0.1 --grbl-setting '$110=5000'",
                                                 out);
  EXPECT_EQ(rc, 3) << out;
  EXPECT_NE(out.find(" 115200 7E2 none"), std::string::npos) << out;
  EXPECT_NE(out.find("$110=5000"), std::string::npos) << out;
}

TEST(SendCli, BadOptionValuesAreUsageErrorsWithTheConfigurationsWords) {
  TempDir dir;
  const std::string send = lastcut_binary() + " send " + write_program(dir, 5) + " --port " + (dir / "x") + " --protocol grbl";
  std::string out;
  EXPECT_EQ(run_command(send + " --parity X", out), 2) << out;
  EXPECT_NE(out.find("lastcut: error: --parity: \"X\" is not one of N, E, O"), std::string::npos) << out;
  EXPECT_EQ(run_command(send + " --data-bits 9", out), 2) << out;
  EXPECT_NE(out.find("--data-bits: 9 is outside 5 .. 8"), std::string::npos) << out;
  EXPECT_EQ(run_command(send + " --grbl-setting G0X10", out), 2) << out;
  EXPECT_NE(out.find("--grbl-setting: \"G0X10\" is not a grbl setting line"), std::string::npos) << out;
  EXPECT_EQ(run_command(send + " --status-poll fast", out), 2) << out;
  EXPECT_NE(out.find("--status-poll: must be a number"), std::string::npos) << out;
}

TEST(SendCli, EveryOptionIsAFlagDocumentedInDriversMd) {
  const std::string guide = testing::read_file(std::filesystem::path(LASTCUT_SOURCE_DIR) / "docs/drivers.md");
  std::string help;
  ASSERT_EQ(run_command(lastcut_binary() + " send --help", help), 0) << help;
  for (const CutterOption& option : cutter_options()) {
    const std::string flag(std::string_view(option.flag).substr(0, option.flag.find(',')));
    EXPECT_NE(help.find(flag), std::string::npos) << flag << " missing from lastcut send --help";
    EXPECT_NE(guide.find("`" + flag), std::string::npos) << flag << " missing from docs/drivers.md";
  }
}

TEST(SendCli, ModbusJobThroughTheCommandLine) {
  TempDir dir;
  const int port = testing::free_loopback_port();
  SimProcess sim({"modbus-tcp", "--port", std::to_string(port), "--cut-s", "0.1"});
  ASSERT_TRUE(sim.ready());
  std::string out;
  const int rc = run_command(lastcut_binary() + " send " + write_program(dir, 50) + " --modbus tcp://127.0.0.1:" +
                                 std::to_string(port) + " --job-id CLI-1 --timeout 2",
                             out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("PLC reports the job done"), std::string::npos) << out;
}

TEST(SendCli, PortsListsWithoutError) {
  std::string out;
  EXPECT_EQ(run_command(lastcut_binary() + " ports", out), 0) << out;
  EXPECT_TRUE(out.find("DEVICE") != std::string::npos || out.find("no serial ports") != std::string::npos) << out;
}

}  // namespace
}  // namespace lastcut::drivers
