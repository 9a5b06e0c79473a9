// The sending half shared by the daemon's two cutter workers: the cut file read byte for byte, and
// the progress monitor's watch ended on every outcome (a worker left "busy" would stop the systemd
// watchdog's feeding for good).
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <string>

#include "daemon/station/watched_send.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut::daemon {
namespace {

TEST(ReadCutProgram, GivesTheStoredBytesExactly) {
  const test::TempDir folder("watched-send");
  const std::string bytes = std::string("IN;SP1;\r\nPU0,0;\0PD10,10;", 25) + "\x03";
  std::ofstream(folder / "cut.plt", std::ios::binary) << bytes;
  const auto program = read_cut_program(folder / "cut.plt");
  ASSERT_TRUE(program);
  EXPECT_EQ(*program, bytes);
}

TEST(ReadCutProgram, RefusesAMissingOrEmptyFile) {
  const test::TempDir folder("watched-send");
  EXPECT_FALSE(read_cut_program(folder / "missing.nc"));
  std::ofstream(folder / "empty.nc").close();
  EXPECT_FALSE(read_cut_program(folder / "empty.nc"));
  EXPECT_FALSE(read_cut_program(folder.path()));  // a folder is no cut file
  EXPECT_FALSE(read_cut_program(folder / ""));     // nor is a batch's folder joined to an empty cut-file name
}

TEST(SendWatched, AFailedSendLeavesNoWorkerBusy) {
  const test::TempDir folder("watched-send");
  ProgressMonitor monitor;
  drivers::CutterConfig config;
  config.protocol = "grbl";
  config.port = (folder / "no-such-port").string();
  config.timeout_s = 1;
  config.name = "bench-1";
  const std::atomic<bool> cancel{false};
  const drivers::SendResult result = send_watched(monitor, "cutter bench-1", "batch B1", config, "G0 X1\n",
                                                  [](const drivers::SendProgress&) {}, cancel);
  EXPECT_EQ(result.outcome, drivers::SendOutcome::Failed) << result.reason;
  // An hour later nothing may count as stuck: the watch ended with the send.
  EXPECT_EQ(monitor.stuck(ProgressMonitor::Clock::now() + std::chrono::hours(1)), "");
}

}  // namespace
}  // namespace lastcut::daemon
