// lastcutd with reference patterns named in sidecars: the real daemon, real generated lasts, and
// patterns made from the mold `lastcut flatten` computes for the same last. A job whose pattern
// matches is cut; one whose pattern has the toe 5 mm off is held for review with the reason; an
// unreadable pattern fails its job with one line, the scan kept.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "daemon_rig.hpp"
#include "engine/mold/mold_dxf.hpp"

namespace lastcut::daemon::testing {
namespace {

std::string job_of(const DaemonRig& rig, const std::string& scan, std::string* folder_out) {
  const DaemonRig::FoundJob job = rig.find_job(scan);
  if (folder_out) *folder_out = job.folder;
  return job.id;
}

// The outline as a plain pattern: one closed LWPOLYLINE in mm, no notch marks (as pattern CAD or
// a traced wax-foil mold has it), the toe pulled `pull_mm` away from the heel.
void write_pattern(const Mold& mold, double pull_mm, const std::filesystem::path& file) {
  Point2 heel = Point2::Zero(), toe = Point2::Zero();
  for (const auto& mark : mold.marks) {
    if (mark.name == "heel") heel = mark.position_mm;
    if (mark.name == "toe") toe = mark.position_mm;
  }
  const Point2 pull = pull_mm * (toe - heel).normalized();
  std::string text = "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\n0\n70\n1\n";
  for (const auto& p : mold.outline.points) {
    const Point2 q = p + std::max(0.0, 1.0 - (p - toe).norm() / 20.0) * pull;
    text += "10\n" + std::to_string(q.x()) + "\n20\n" + std::to_string(q.y()) + "\n";
  }
  write_text(file, text + "0\nENDSEC\n0\nEOF\n");
}

TEST(DaemonReferenceReview, MatchingPatternIsCutDistortedIsHeldUnreadableFails) {
  RigOptions options;
  DaemonRig rig("reference-review", options);
  const auto staging = rig.root() / "staging";
  std::filesystem::create_directories(staging);
  const auto last = small_last(41, "left", 3);
  // The mold the daemon will compute, made the same way by the command line.
  ASSERT_EQ(run_command({binary("lastcut").string(), "flatten", last.string(), "-o", (staging / "flat").string()},
                        staging / "flatten.log"),
            0)
      << read_text(staging / "flatten.log");
  const Mold medial = read_mold_dxf(staging / "flat" / "medial.dxf");
  const auto patterns = rig.watch() / "patterns";
  std::filesystem::create_directories(patterns);
  write_pattern(medial, 0.0, patterns / "good-m.dxf");
  write_pattern(medial, 5.0, patterns / "toe-m.dxf");
  write_text(patterns / "broken-m.dxf", "not a drawing\n");

  rig.start_cutters();
  rig.start_daemon();
  for (const std::string name : {"good", "toe", "broken"}) {
    write_variant(last, staging / (name + ".stl"), name);  // different bytes: no duplicates
    write_text(rig.watch() / (name + ".job.toml"), "order = \"" + name + "\"\nreference_medial = \"patterns/" + name + "-m.dxf\"\n");
    drop(staging / (name + ".stl"), rig.watch(), name + ".stl");
  }
  ASSERT_TRUE(wait_until(
      [&] { return rig.jobs("done").size() + rig.jobs("held").size() + rig.jobs("failed").size() == 3; }, 120))
      << read_text(rig.daemon_log());
  // The patterns are copies in the jobs: removing the originals changes nothing.
  std::filesystem::remove_all(patterns);
  EXPECT_EQ(rig.stop_daemon(), 0);
  rig.stop_cutters();

  std::string folder;
  const std::string good = job_of(rig, "good.stl", &folder);
  ASSERT_EQ(folder, "done") << read_text(rig.daemon_log());
  const auto good_report = nlohmann::json::parse(read_text(rig.spool() / "done" / good / "report.json"));
  const auto& comparison = good_report.at("compare").at("medial");
  EXPECT_GE(comparison.at("overlap_pct").get<double>(), 99.99);
  EXPECT_TRUE(comparison.at("within_tolerance").get<bool>());
  EXPECT_EQ(comparison.at("corners").size(), 4u);
  EXPECT_TRUE(std::filesystem::exists(rig.spool() / "done" / good / "molds" / "compare-medial.svg"));
  EXPECT_TRUE(std::filesystem::exists(rig.spool() / "done" / good / "reference-medial.dxf"));

  const std::string toe = job_of(rig, "toe.stl", &folder);
  ASSERT_EQ(folder, "held");
  const std::string reason = rig.jobs("held").at(toe).value("reason", "");
  EXPECT_TRUE(reason.starts_with("held for review: corner toe of the medial mold 5.0 mm off the reference pattern "
                                 "(tolerance 2.0 mm)"))
      << reason;
  const auto toe_report = nlohmann::json::parse(read_text(rig.spool() / "held" / toe / "report.json"));
  for (const auto& corner : toe_report.at("compare").at("medial").at("corners")) {
    if (corner.at("name") == "toe") EXPECT_NEAR(corner.at("margin_mm").get<double>(), 5.0, 0.1);
    else EXPECT_LT(corner.at("margin_mm").get<double>(), 0.5) << corner.dump();
  }
  EXPECT_TRUE(std::filesystem::exists(rig.spool() / "held" / toe / "molds" / "compare-medial.json"));

  const std::string broken = job_of(rig, "broken.stl", &folder);
  ASSERT_EQ(folder, "failed");
  const std::string failed_reason = rig.jobs("failed").at(broken).value("reason", "");
  EXPECT_NE(failed_reason.find("reference pattern: "), std::string::npos) << failed_reason;
  EXPECT_NE(failed_reason.find("is not a DXF file: line 1 is not a group code"), std::string::npos) << failed_reason;
  EXPECT_EQ(failed_reason.find('\n'), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(rig.spool() / "failed" / broken / "broken.stl")) << "the scan is kept";
}

TEST(DaemonReferenceReview, MissingPatternFailsAtTheClaim) {
  DaemonRig rig("reference-missing", RigOptions{});
  const auto staging = rig.root() / "staging";
  std::filesystem::create_directories(staging);
  write_variant(small_last(41, "left", 3), staging / "lost.stl", "lost");
  rig.start_cutters();
  rig.start_daemon();
  write_text(rig.watch() / "lost.job.toml", "reference_lateral = \"nowhere.svg\"\n");
  drop(staging / "lost.stl", rig.watch(), "lost.stl");
  ASSERT_TRUE(wait_until([&] { return rig.jobs("failed").size() == 1; }, 60)) << read_text(rig.daemon_log());
  EXPECT_EQ(rig.stop_daemon(), 0);
  rig.stop_cutters();
  const auto failed = rig.jobs("failed");
  const auto& [id, state] = *failed.begin();
  EXPECT_TRUE(state.value("reason", "").starts_with("reference pattern nowhere.svg for the lateral mold is not in "))
      << state.value("reason", "");
  EXPECT_TRUE(std::filesystem::exists(rig.spool() / "failed" / id / "lost.stl"));
}

}  // namespace
}  // namespace lastcut::daemon::testing
