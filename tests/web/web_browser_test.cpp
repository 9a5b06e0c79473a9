// The operator page in a real browser (Debian's chromium under puppeteer-core, tests/node): a
// lastcutd on a scratch spool whose first job is held by a cutter that dropped the line, then
// operator_page_browser.js drives the page. It fails unless, without a reload, a dropped scan moves
// through the queue to Done, the held job shows its reason, its requeue is refused without the
// token and done with it (the layout on the cutter's card marking the piece being cut), and a hide
// uploaded from the page is placed on the cutter's table.
#include <gtest/gtest.h>

#include "tests/daemon/daemon_rig.hpp"
#include "tests/daemon/hide_samples.hpp"
#include "tests/support/loopback_port.hpp"
#include "tests/web/web_client.hpp"

namespace lastcut::daemon::testing {
namespace {

TEST(OperatorPageInABrowser, FollowsAScanRequeuesAHeldJobAndLoadsAHide) {
  const int port = lastcut::test::free_loopback_port();
  const std::string token = "b7e1c9d2a4f6e8d0-anna";
  RigOptions options;
  options.sim_faults = {{"cutter-1", "drop-at-line=20"}};
  options.extra_paths = "hides = \"hides\"\n";
  options.extra_config = "[web]\nlisten = \"127.0.0.1:" + std::to_string(port) + "\"\nassets = \"" +
                         std::string(LASTCUT_SOURCE_DIR) + "/daemon/web/assets\"\n[web.tokens]\nanna = \"" + token + "\"\n"
                         "[materials.leather]\nkind = \"hide\"\ncutter = \"cutter-1\"\nrotation_step_deg = 90\n";
  DaemonRig rig("web-browser", options);
  rig.start_cutters();
  rig.start_daemon();
  const auto staging = rig.root() / "staging";
  std::filesystem::create_directories(staging);
  write_variant(small_last(41, "right", 7), staging / "held.stl", "held");
  drop(staging / "held.stl", rig.watch(), "held.stl");
  ASSERT_TRUE(wait_until([&] { return rig.jobs("held").size() == 1; }, 120)) << read_text(rig.daemon_log());
  // The alarm cleared: a cutter that works, under the same link, moving at its real speed (so that
  // the page can be seen during a cut), with an 8 KiB buffer (the simulator's 1 KiB one overflows
  // at real speed on a PD longer than its free space: it does not run a PD's pairs as they come).
  // The held job stays held until requeued.
  rig.stop_cutters();
  Process cutter({binary("lastcut-sim").string(), "hpgl", "--link", (rig.root() / "cutter-1.tty").string(),
                  "--record", (rig.root() / "record2").string(), "--time-scale", "1", "--buffer", "8192"},
                 rig.root() / "sim2.log");
  write_variant(small_last(42, "left", 7), staging / "browser-scan.stl", "browser");
  // A job of the hide material: it waits for the hide the page uploads, which is then nested and cut.
  write_variant(small_last(39, "right", 8), staging / "leather.stl", "leather");
  write_text(rig.watch() / "leather.job.toml", "material = \"leather\"\n");
  drop(staging / "leather.stl", rig.watch(), "leather.stl");
  write_hide_dxf(staging / "hide-7.dxf", 1200, 900, false);
  const auto shots = rig.root() / "shots";
  std::filesystem::create_directories(shots);

  const auto log = rig.root() / "browser.log";
  const int status = run_command({"node", std::string(LASTCUT_SOURCE_DIR) + "/tests/web/operator_page_browser.js",
                                  "http://127.0.0.1:" + std::to_string(port) + "/", token, rig.watch().string(),
                                  (staging / "browser-scan.stl").string(), (staging / "hide-7.dxf").string(),
                                  shots.string(), std::string(LASTCUT_SOURCE_DIR) + "/tests/node/node_modules"},
                                 log);
  EXPECT_EQ(status, 0) << read_text(log) << "\n--- lastcutd:\n" << read_text(rig.daemon_log());
  EXPECT_TRUE(std::filesystem::exists(rig.root() / "hides" / "hide-7.dxf") ||
              read_text(rig.daemon_log()).find("hide-7") != std::string::npos);
  EXPECT_NE(read_text(rig.daemon_log()).find("(token anna) requeued job"), std::string::npos);
  EXPECT_EQ(rig.jobs("done").size(), 3u) << "the dropped scan, the requeued job and the job cut on the hide";
  EXPECT_EQ(rig.stop_daemon(), 0);
  cutter.stop();
}

}  // namespace
}  // namespace lastcut::daemon::testing
