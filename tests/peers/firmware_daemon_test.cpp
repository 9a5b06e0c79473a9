// lastcutd end to end with the REAL grbl 1.1h firmware as its cutter (tests/peers/run_grbl_firmware.sh
// on a pty): a last dropped into the watch folder is flattened, nested and cut with the shipped
// grbl-drag-knife profile (knife and pens: the pens go down and up with M8/M9, buffer syncs), and the
// firmware executes every line of the cut file to its end.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <regex>
#include <sstream>

#include "tests/daemon/daemon_rig.hpp"

namespace lastcut::daemon::testing {
namespace {

// Motion lines of a cut file, and its last target in firmware steps (grbl's default 250 steps/mm).
struct CutFile {
  int motion_lines = 0;
  int pen_downs = 0;  // M8: a buffer sync on grbl
  long last_x_steps = 0, last_y_steps = 0;
};

CutFile read_cut_file(const std::filesystem::path& file) {
  CutFile cut;
  std::istringstream in(read_text(file));
  const std::regex motion(R"(^G[0-3]\b)");
  const std::regex word(R"(([XY])(-?[0-9.]+))");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("M8", 0) == 0) ++cut.pen_downs;
    if (!std::regex_search(line, motion)) continue;
    ++cut.motion_lines;
    for (std::sregex_iterator it(line.begin(), line.end(), word), end; it != end; ++it) {
      const long steps = std::lround(std::stod((*it)[2]) * 250);
      ((*it)[1] == "X" ? cut.last_x_steps : cut.last_y_steps) = steps;
    }
  }
  return cut;
}

TEST(GrblFirmwareDaemon, ALastDroppedInTheWatchFolderIsCutOnTheRealFirmware) {
  RigOptions options;
  options.grbl_cutters = {"cutter-1"};
  options.grbl_firmware = GRBL_FIRMWARE_EXE;
  options.batch_window_s = 1.0;
  // Fast axes, so the cut takes seconds, not the minutes of grbl's defaults.
  options.extra_config =
      "grbl_settings = [\"$110=60000\", \"$111=60000\", \"$112=60000\", \"$120=500000\", \"$121=500000\", "
      "\"$122=500000\"]\n";
  DaemonRig rig("firmware-e2e", options);
  ASSERT_NO_FATAL_FAILURE(rig.start_cutters());
  ASSERT_NO_FATAL_FAILURE(rig.start_daemon());

  // One last (two molds): the simulated firmware cuts in real time, and the suite has a budget.
  write_variant(small_last(40, "left", 5), rig.root() / "left.stl", "firmware-left");
  drop(rig.root() / "left.stl", rig.watch(), "left.stl");
  ASSERT_TRUE(wait_until([&] { return rig.settled(1); }, 600)) << read_text(rig.daemon_log());
  const auto done = rig.jobs("done");
  ASSERT_EQ(done.size(), 1u) << read_text(rig.daemon_log());

  // Each batch's cut file ran once: the firmware's blocks cover every motion line (an arc adds
  // blocks, a line never goes missing), and the last block ends at the last file's last target.
  std::set<std::filesystem::path> cut_files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(rig.spool() / "done")) {
    if (entry.path().filename() == "cut.nc") cut_files.insert(std::filesystem::canonical(entry.path()));
  }
  ASSERT_FALSE(cut_files.empty());
  int motion_lines = 0, pen_downs = 0;
  std::set<std::pair<long, long>> last_targets;
  for (const auto& file : cut_files) {
    const CutFile cut = read_cut_file(file);
    motion_lines += cut.motion_lines;
    pen_downs += cut.pen_downs;
    last_targets.insert({cut.last_x_steps, cut.last_y_steps});
  }
  EXPECT_GT(pen_downs, 0) << "the cut files never lowered a pen: the buffer syncs went untested";
  const auto blocks = rig.firmware_blocks("cutter-1");
  EXPECT_GE(static_cast<int>(blocks.size()), motion_lines) << "a motion line never reached the planner";
  ASSERT_FALSE(blocks.empty());
  long x = 0, y = 0;
  ASSERT_EQ(std::sscanf(blocks.back().c_str(), "%ld, %ld,", &x, &y), 2) << blocks.back();
  EXPECT_EQ(last_targets.count({x, y}), 1u) << "the firmware stopped at " << x << ", " << y
                                           << " steps, not at the end of a cut file";
  EXPECT_EQ(rig.stop_daemon(), 0);
}

}  // namespace
}  // namespace lastcut::daemon::testing
