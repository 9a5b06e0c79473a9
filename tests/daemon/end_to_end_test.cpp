// lastcutd end to end with the real binaries: generated lasts dropped into the watch folder,
// a simulated grbl table and HPGL plotters on pseudo-terminals, and the spool and the simulators' records
// checked afterwards. Proves: every job reaches the right cutter exactly once, bad input ends
// in failed/ with the reason, duplicates follow the policy, a cutter fault holds only that
// cutter's job, a held job is cut after `lastcut requeue`, and a clean stop leaves nothing in work/.
#include <gtest/gtest.h>

#include <csignal>
#include <thread>

#include "daemon_rig.hpp"

namespace lastcut::daemon::testing {
namespace {

// Job id of the job whose scan had this name, in any folder.
std::string job_of(const DaemonRig& rig, const std::string& scan, std::string* folder_out = nullptr) {
  const DaemonRig::FoundJob job = rig.find_job(scan);
  if (folder_out) *folder_out = job.folder;
  return job.id;
}

TEST(DaemonEndToEnd, TenScansReachTheRightCutterExactlyOnce) {
  RigOptions options;
  options.cutters = {"cutter-1", "cutter-2"};
  options.grbl_cutters = {"cutter-1"};  // G-code to a grbl table; cutter-2 is an HPGL plotter
  options.batch_window_s = 1.0;
  DaemonRig rig("e2e-ten", options);
  rig.start_cutters();
  rig.start_daemon();

  const auto staging = rig.root() / "staging";
  std::filesystem::create_directories(staging);
  const std::vector<std::pair<int, std::string>> lasts = {{38, "left"}, {39, "right"}, {40, "left"},
                                                          {41, "right"}, {42, "left"}, {43, "right"}};
  for (std::size_t i = 0; i < lasts.size(); ++i) {
    write_variant(small_last(lasts[i].first, lasts[i].second, 1), staging / ("good-" + std::to_string(i) + ".stl"),
                  std::to_string(i));
  }
  // A cut-off binary STL (the upload broke), and bytes that are no mesh at all.
  const std::string good = read_text(staging / "good-0.stl");
  write_text(staging / "truncated.stl", good.substr(0, good.size() / 3));
  write_text(staging / "garbage.stl", std::string(4000, 'z'));
  // One for the second cutter, with an order number.
  write_variant(small_last(44, "left", 2), staging / "order-4711.stl", "4711");
  write_text(rig.watch() / "order-4711.job.toml", "order = \"4711\"\ncutter = \"cutter-2\"\nsize = \"EU 44\"\n");

  for (std::size_t i = 0; i < lasts.size(); ++i) {
    drop(staging / ("good-" + std::to_string(i) + ".stl"), rig.watch(), "good-" + std::to_string(i) + ".stl");
  }
  drop(staging / "truncated.stl", rig.watch(), "truncated.stl");
  drop(staging / "garbage.stl", rig.watch(), "garbage.stl");
  drop(staging / "order-4711.stl", rig.watch(), "order-4711.stl");
  // The duplicate comes once the original has been taken (same bytes as good-0).
  ASSERT_TRUE(wait_until([&] { return !job_of(rig, "good-0.stl").empty(); }, 30));
  drop(staging / "good-0.stl", rig.watch(), "again-good-0.stl");

  ASSERT_TRUE(wait_until([&] { return rig.settled(10); }, 120)) << read_text(rig.daemon_log());
  EXPECT_EQ(rig.stop_daemon(), 0);
  rig.stop_cutters();

  const auto done = rig.jobs("done");
  const auto failed = rig.jobs("failed");
  EXPECT_EQ(done.size(), 8u) << read_text(rig.daemon_log());
  EXPECT_EQ(failed.size(), 2u);
  EXPECT_EQ(rig.jobs("held").size(), 0u);

  std::string folder;
  const std::string truncated = job_of(rig, "truncated.stl", &folder);
  EXPECT_EQ(folder, "failed");
  EXPECT_NE(failed.at(truncated).value("reason", "").find("cut off"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(rig.spool() / "failed" / truncated / "truncated.stl")) << "original kept";
  const std::string garbage = job_of(rig, "garbage.stl", &folder);
  EXPECT_EQ(folder, "failed");
  EXPECT_FALSE(failed.at(garbage).value("reason", "").empty());

  const std::string duplicate = job_of(rig, "again-good-0.stl", &folder);
  EXPECT_EQ(folder, "done");
  EXPECT_EQ(done.at(duplicate).value("stage", ""), "skipped");
  EXPECT_EQ(done.at(duplicate).value("duplicate_of", ""), job_of(rig, "good-0.stl"));

  const std::string on_cutter_1 = rig.received("cutter-1");
  const std::string on_cutter_2 = rig.received("cutter-2");
  for (std::size_t i = 0; i < lasts.size(); ++i) {
    const std::string id = job_of(rig, "good-" + std::to_string(i) + ".stl");
    EXPECT_EQ(done.at(id).value("stage", ""), "cut");
    // The exact G-code of its batch reached the grbl table cutter-1 once, and never cutter-2;
    // the job's own comment line says which program carried it.
    const std::string cut = read_text(rig.spool() / "done" / id / rig.cut_file_name("cutter-1"));
    ASSERT_FALSE(cut.empty()) << id;
    EXPECT_EQ(count_occurrences(on_cutter_1, cut), 1) << id;
    EXPECT_EQ(count_occurrences(on_cutter_2, cut), 0) << id;
    EXPECT_EQ(count_occurrences(on_cutter_1, "; lastcut job " + id + "\n"), 1) << id;
    const auto report = nlohmann::json::parse(read_text(rig.spool() / "done" / id / "report.json"));
    EXPECT_EQ(report.at("batch").value("cutter", ""), "cutter-1");
    EXPECT_GT(report.at("batch").value("utilisation", 0.0), 0.0);
    EXPECT_TRUE(std::filesystem::exists(rig.spool() / "done" / id / "preview.svg"));
    EXPECT_TRUE(std::filesystem::exists(rig.spool() / "done" / id / "molds" / "report.json"));
    // Each half is labelled with the scan's name, its foot and which half it is, in the layout
    // and in the preview the operator checks before cutting.
    const std::string foot = lasts[i].second == "left" ? " L " : " R ";
    const std::string layout = read_text(rig.spool() / "done" / id / "layout.json");
    const std::string preview = read_text(rig.spool() / "done" / id / "preview.svg");
    for (const char* half : {"med", "lat"}) {
      const std::string label = "#good-" + std::to_string(i) + foot + half;
      EXPECT_NE(layout.find("\"" + label + "\""), std::string::npos) << label << " not in the layout of " << id;
      EXPECT_NE(preview.find(" " + label + "</title>"), std::string::npos) << label << " not in the preview of " << id;
    }
  }
  const std::string order = job_of(rig, "order-4711.stl");
  EXPECT_EQ(done.at(order).at("ticket").value("order", ""), "4711");
  const std::string order_cut = read_text(rig.spool() / "done" / order / rig.cut_file_name("cutter-2"));
  ASSERT_FALSE(order_cut.empty());
  EXPECT_EQ(count_occurrences(on_cutter_2, order_cut), 1);
  EXPECT_EQ(count_occurrences(on_cutter_1, order_cut), 0);
  EXPECT_FALSE(std::filesystem::exists(rig.spool() / "done" / duplicate / "cut.plt")) << "the duplicate is not cut";
  EXPECT_FALSE(std::filesystem::exists(rig.spool() / "done" / duplicate / "cut.nc")) << "the duplicate is not cut";
  EXPECT_TRUE(std::filesystem::exists(rig.spool() / "done" / order / "order-4711.job.toml"));
  // The order's pieces carry its number and size instead of the scan's name.
  const std::string order_layout = read_text(rig.spool() / "done" / order / "layout.json");
  EXPECT_NE(order_layout.find("\"#4711 EU44 L med\""), std::string::npos) << order_layout.substr(0, 2000);
  EXPECT_NE(order_layout.find("\"#4711 EU44 L lat\""), std::string::npos);

  // The operator's log names the order and says where bad jobs went.
  const std::string log = read_text(rig.daemon_log());
  EXPECT_NE(log.find("order 4711 (order-4711.stl)"), std::string::npos);
  EXPECT_NE(log.find("truncated.stl [job " + truncated + "]: the file is cut off"), std::string::npos) << log;
  EXPECT_NE(log.find("moved to failed/"), std::string::npos);
}

TEST(DaemonEndToEnd, ACutterFaultHoldsItsJobWhileTheOtherCutterKeepsWorking) {
  RigOptions options;
  options.cutters = {"cutter-1", "cutter-2"};
  options.sim_faults = {{"cutter-2", "drop-at-line=20"}};
  DaemonRig rig("e2e-fault", options);
  rig.start_cutters();
  rig.start_daemon();
  const auto staging = rig.root() / "staging";
  std::filesystem::create_directories(staging);
  write_variant(small_last(40, "left", 3), staging / "a.stl", "a");
  write_variant(small_last(41, "right", 3), staging / "b.stl", "b");
  write_variant(small_last(42, "left", 3), staging / "faulty.stl", "faulty");
  write_text(rig.watch() / "faulty.job.json", R"({"order": "777", "cutter": "cutter-2"})");
  drop(staging / "faulty.stl", rig.watch(), "faulty.stl");
  drop(staging / "a.stl", rig.watch(), "a.stl");
  drop(staging / "b.stl", rig.watch(), "b.stl");
  ASSERT_TRUE(wait_until([&] { return rig.settled(3); }, 120)) << read_text(rig.daemon_log());

  std::string folder;
  const std::string faulty = job_of(rig, "faulty.stl", &folder);
  EXPECT_EQ(folder, "held");
  const std::string reason = rig.jobs("held").at(faulty).value("reason", "");
  EXPECT_NE(reason.find("cutter cutter-2 stopped while cutting"), std::string::npos) << reason;
  EXPECT_NE(job_of(rig, "a.stl", &folder), "");
  EXPECT_EQ(folder, "done");
  job_of(rig, "b.stl", &folder);
  EXPECT_EQ(folder, "done");
  // Never resent on its own: wait a few retry intervals, it stays held.
  std::this_thread::sleep_for(std::chrono::seconds(2));
  EXPECT_EQ(rig.jobs("held").size(), 1u);

  // `lastcut status` shows it; the operator clears the alarm (new simulator) and requeues.
  const auto status_log = rig.root() / "status.txt";
  EXPECT_EQ(run_command({binary("lastcut").string(), "status", "--config", rig.config_file().string()}, status_log), 0);
  EXPECT_NE(read_text(status_log).find(faulty), std::string::npos) << read_text(status_log);
  EXPECT_NE(read_text(status_log).find("lastcutd: running"), std::string::npos);
  rig.stop_cutters();
  const auto requeue_log = rig.root() / "requeue.txt";
  EXPECT_EQ(run_command({binary("lastcut").string(), "requeue", faulty, "--config", rig.config_file().string()},
                        requeue_log), 0) << read_text(requeue_log);
  // Restart the simulators without the fault, under the same links.
  Process cutter_1({binary("lastcut-sim").string(), "hpgl", "--link", (rig.root() / "cutter-1.tty").string(),
                    "--record", (rig.root() / "record2-cutter-1").string(), "--time-scale", "0"},
                   rig.root() / "sim2-1.log");
  Process cutter_2({binary("lastcut-sim").string(), "hpgl", "--link", (rig.root() / "cutter-2.tty").string(),
                    "--record", (rig.root() / "record2-cutter-2").string(), "--time-scale", "0"},
                   rig.root() / "sim2-2.log");
  ASSERT_TRUE(wait_until([&] { return rig.jobs("done").count(faulty) == 1; }, 60)) << read_text(rig.daemon_log());
  EXPECT_EQ(rig.stop_daemon(), 0);
  cutter_2.signal(SIGTERM);
  cutter_2.wait(10);
  EXPECT_EQ(count_occurrences(read_text(rig.root() / "record2-cutter-2" / "hpgl-received.hpgl"),
                              read_text(rig.spool() / "done" / faulty / "cut.plt")), 1);
  cutter_1.signal(SIGTERM);
  cutter_1.wait(10);
}

// A grbl table that still answers but no longer moves (its status says Run at one position for
// good) must not keep `lastcut status` at "cutting (n %)" forever: after grbl_stall_s the cut is
// stopped (feed hold, reset), the job held with the reason, and nothing is resent on its own.
TEST(DaemonEndToEnd, AGrblThatAnswersButNoLongerMovesIsHeldAndNotResent) {
  RigOptions options;
  options.grbl_cutters = {"cutter-1"};
  options.sim_faults = {{"cutter-1", "freeze-at-line=30"}};
  options.extra_config = "grbl_stall_s = 2.0\n";  // lands in [cutters.cutter-1], the last table
  DaemonRig rig("e2e-frozen", options);
  rig.start_cutters();
  rig.start_daemon();
  write_variant(small_last(43, "left", 3), rig.root() / "frozen.stl", "frozen");
  drop(rig.root() / "frozen.stl", rig.watch(), "frozen.stl");
  ASSERT_TRUE(wait_until([&] { return rig.settled(1); }, 120)) << read_text(rig.daemon_log());

  std::string folder;
  const std::string frozen = job_of(rig, "frozen.stl", &folder);
  EXPECT_EQ(folder, "held");
  const std::string reason = rig.jobs("held").at(frozen).value("reason", "");
  EXPECT_NE(reason.find("answers but has neither moved nor taken a line for 2 s"), std::string::npos) << reason;
  std::this_thread::sleep_for(std::chrono::seconds(2));
  EXPECT_EQ(rig.jobs("held").size(), 1u) << "a stalled cut is never resent on its own";
  const auto status_log = rig.root() / "status.txt";
  EXPECT_EQ(run_command({binary("lastcut").string(), "status", "--config", rig.config_file().string()}, status_log), 0);
  EXPECT_NE(read_text(status_log).find("neither moved"), std::string::npos) << read_text(status_log);
  EXPECT_EQ(rig.stop_daemon(), 0);
}

TEST(DaemonEndToEnd, RefusedConfigurationExitsWithConfigStatus) {
  DaemonRig rig("e2e-config", RigOptions{});
  write_text(rig.config_file(), read_text(rig.config_file()) + "[cutters.cutter-1.extra]\n");
  const auto log = rig.root() / "check.txt";
  EXPECT_EQ(run_command({binary("lastcutd").string(), "--check-config", rig.config_file().string()}, log), 78);
  EXPECT_NE(read_text(log).find("cutters.cutter-1.extra"), std::string::npos) << read_text(log);
  EXPECT_EQ(run_command({binary("lastcutd").string(), "--config", rig.config_file().string()}, log), 78);
}

TEST(DaemonEndToEnd, BadReloadKeepsTheRunningConfiguration) {
  DaemonRig rig("e2e-reload", RigOptions{});
  rig.start_cutters();
  rig.start_daemon();
  const std::string good = read_text(rig.config_file());
  write_text(rig.config_file(), good + "[jobs.extra]\n");
  rig.daemon()->signal(SIGHUP);
  ASSERT_TRUE(wait_until([&] { return read_text(rig.daemon_log()).find("reload refused") != std::string::npos; }, 10));
  write_text(rig.config_file(), good);
  rig.daemon()->signal(SIGHUP);
  ASSERT_TRUE(wait_until([&] { return read_text(rig.daemon_log()).find("configuration reloaded") != std::string::npos; }, 10));
  // Still working after both reloads.
  write_variant(small_last(40, "left", 3), rig.root() / "x.stl", "reload");
  drop(rig.root() / "x.stl", rig.watch(), "x.stl");
  ASSERT_TRUE(wait_until([&] { return rig.settled(1); }, 60)) << read_text(rig.daemon_log());
  EXPECT_EQ(rig.jobs("done").size(), 1u);
  EXPECT_EQ(rig.stop_daemon(), 0);
}

}  // namespace
}  // namespace lastcut::daemon::testing
