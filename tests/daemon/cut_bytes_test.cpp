// The bytes a cutter receives are the cut file stored in the spool, to the byte: lastcutd adds
// nothing on the way (the batch and job ids are written into the file when it is made). Real
// binaries: lastcutd, a simulated grbl table and a simulated HPGL plotter on pseudo-terminals,
// whose records are compared with the files in done/.
#include <gtest/gtest.h>

#include "daemon_rig.hpp"

namespace lastcut::daemon::testing {
namespace {

// The one job of the done/ folder whose scan had this name.
std::string done_job(const DaemonRig& rig, const std::string& scan) {
  for (const auto& [id, state] : rig.jobs("done"))
    if (state.value("scan", "") == scan) return id;
  return {};
}

TEST(DaemonCutBytes, EachCutterRecordedExactlyTheStoredCutFile) {
  RigOptions options;
  options.cutters = {"cutter-1", "cutter-2"};
  options.grbl_cutters = {"cutter-1"};  // G-code to a grbl table; cutter-2 is an HPGL plotter
  DaemonRig rig("cut-bytes", options);
  rig.start_cutters();
  rig.start_daemon();

  const auto staging = rig.root() / "staging";
  std::filesystem::create_directories(staging);
  write_variant(small_last(40, "left", 1), staging / "for-grbl.stl", "grbl");
  write_variant(small_last(41, "right", 2), staging / "for-plotter.stl", "hpgl");
  write_text(rig.watch() / "for-plotter.job.toml", "cutter = \"cutter-2\"\n");
  drop(staging / "for-grbl.stl", rig.watch(), "for-grbl.stl");
  drop(staging / "for-plotter.stl", rig.watch(), "for-plotter.stl");

  ASSERT_TRUE(wait_until([&] { return rig.settled(2); }, 120)) << read_text(rig.daemon_log());
  EXPECT_EQ(rig.stop_daemon(), 0);
  rig.stop_cutters();

  for (const auto& [scan, cutter] : {std::pair{"for-grbl.stl", "cutter-1"}, std::pair{"for-plotter.stl", "cutter-2"}}) {
    const std::string id = done_job(rig, scan);
    ASSERT_FALSE(id.empty()) << scan << " not done:\n" << read_text(rig.daemon_log());
    const std::string stored = read_text(rig.spool() / "done" / id / rig.cut_file_name(cutter));
    ASSERT_FALSE(stored.empty()) << id;
    const std::string received = rig.received(cutter);
    EXPECT_EQ(received.size(), stored.size()) << cutter;
    EXPECT_TRUE(received == stored) << cutter << ": the machine did not receive the stored cut file";
  }
  // The G-code names its batch and job in the file itself.
  const std::string gcode = read_text(rig.spool() / "done" / done_job(rig, "for-grbl.stl") / "cut.nc");
  EXPECT_NE(gcode.find("; lastcut job " + done_job(rig, "for-grbl.stl") + "\n"), std::string::npos);
  EXPECT_NE(gcode.find("; lastcut batch "), std::string::npos);
}

}  // namespace
}  // namespace lastcut::daemon::testing
