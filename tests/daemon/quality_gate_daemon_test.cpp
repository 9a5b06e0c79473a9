// lastcutd and the mold quality gate (engine/scan/mold_quality_gate.hpp), with the real binaries:
// a scan whose molds fail the gate (here: a limit no real mold meets) is held with the reason and
// its stretch pictures, is never nested or cut, stays held when requeued under the same limits,
// and is cut once when requeued after the operator raised the limit (SIGHUP). A scan dropped
// afterwards is cut as usual, and the cutter receives nothing else.
#include <gtest/gtest.h>

#include <csignal>
#include <string>

#include "daemon_rig.hpp"

namespace lastcut::daemon::testing {
namespace {

std::string job_in(const DaemonRig& rig, const std::string& folder, const std::string& scan) {
  for (const auto& [id, state] : rig.jobs(folder))
    if (state.value("scan", "") == scan) return id;
  return {};
}

int count_text(const std::string& text, const std::string& needle) {
  int count = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++count;
  return count;
}

TEST(DaemonQualityGate, BadMoldsAreHeldNeverCutAndCutOnceAfterARequeueUnderRaisedLimits) {
  // A p95 stretch of exactly 1 is a perfect isometry no real last has: every mold is beyond this
  // gate, so the scan stands for one whose molds went wrong, deterministically.
  RigOptions options;
  options.extra_config = "\n[quality]\nmax_p95_stretch = 1.0\n";
  DaemonRig rig("quality-gate", options);
  const auto staging = rig.root() / "staging";
  std::filesystem::create_directories(staging);
  write_variant(small_last(42, "left", 3), staging / "bad.stl", "bad");
  write_variant(small_last(42, "left", 3), staging / "good.stl", "good");

  rig.start_cutters();
  rig.start_daemon();
  drop(staging / "bad.stl", rig.watch(), "bad.stl");
  ASSERT_TRUE(wait_until([&] { return !job_in(rig, "held", "bad.stl").empty(); }, 120)) << read_text(rig.daemon_log());
  const std::string id = job_in(rig, "held", "bad.stl");
  const auto held_dir = rig.spool() / "held" / id;
  const std::string reason = rig.jobs("held").at(id).value("reason", "");
  EXPECT_EQ(reason.rfind("mold quality: medial p95 stretch ", 0), 0u) << reason;
  EXPECT_NE(reason.find(" > 1; lateral p95 stretch "), std::string::npos) << reason;
  EXPECT_NE(reason.find("; stretch pictures in molds/"), std::string::npos) << reason;
  // The log line follows the move to held/ by a moment.
  EXPECT_TRUE(wait_until([&] { return read_text(rig.daemon_log()).find(reason) != std::string::npos; }, 10))
      << read_text(rig.daemon_log());
  EXPECT_TRUE(std::filesystem::exists(held_dir / "molds" / "medial.svg"));
  EXPECT_FALSE(std::filesystem::exists(held_dir / "items.json")) << "held bad molds must not be nestable";
  const auto report = nlohmann::json::parse(read_text(held_dir / "report.json"));
  EXPECT_FALSE(report["measures"]["quality"]["passed"].get<bool>());
  EXPECT_TRUE(std::filesystem::exists(held_dir / "bad.stl")) << "the scan stays with the job";

  // Requeued under the same limits: computed again and held again, still not cut.
  const auto requeue_log = rig.root() / "requeue.txt";
  const std::vector<std::string> requeue{binary("lastcut").string(), "requeue", id, "--config", rig.config_file().string()};
  ASSERT_EQ(run_command(requeue, requeue_log), 0) << read_text(requeue_log);
  ASSERT_TRUE(wait_until([&] { return count_text(read_text(rig.daemon_log()), reason) >= 2 && !job_in(rig, "held", "bad.stl").empty(); },
                         60))
      << read_text(rig.daemon_log());
  EXPECT_TRUE(job_in(rig, "done", "bad.stl").empty());

  // The operator raises the limit (SIGHUP applies it at once) and requeues: cut once.
  std::string config = read_text(rig.config_file());
  config.replace(config.find("max_p95_stretch = 1.0"), 21, "max_p95_stretch = 1.5");
  write_text(rig.config_file(), config);
  rig.daemon()->signal(SIGHUP);
  ASSERT_TRUE(wait_until([&] { return read_text(rig.daemon_log()).find("configuration reloaded") != std::string::npos; }, 10))
      << read_text(rig.daemon_log());
  ASSERT_EQ(run_command(requeue, requeue_log), 0) << read_text(requeue_log);
  ASSERT_TRUE(wait_until([&] { return !job_in(rig, "done", "bad.stl").empty(); }, 120)) << read_text(rig.daemon_log());
  drop(staging / "good.stl", rig.watch(), "good.stl");
  ASSERT_TRUE(wait_until([&] { return !job_in(rig, "done", "good.stl").empty(); }, 120)) << read_text(rig.daemon_log());
  EXPECT_EQ(rig.stop_daemon(), 0);
  rig.stop_cutters();

  const std::string received = rig.received("cutter-1");
  const std::string bad_cut = read_text(rig.spool() / "done" / id / rig.cut_file_name("cutter-1"));
  const std::string good_cut =
      read_text(rig.spool() / "done" / job_in(rig, "done", "good.stl") / rig.cut_file_name("cutter-1"));
  ASSERT_FALSE(bad_cut.empty());
  EXPECT_EQ(count_text(received, bad_cut), 1);
  EXPECT_EQ(count_text(received, good_cut), 1);
  EXPECT_EQ(received.size(), bad_cut.size() + good_cut.size()) << "nothing else reached the cutter";
}

}  // namespace
}  // namespace lastcut::daemon::testing
