// The scan-to-molds pipeline on generated lasts:
//  - repeatability: two scans of one last (other pose, 0.2 mm noise, other triangle density, a few
//    holes) give molds whose outlines agree within 1 mm after rigid alignment;
//  - quality on a 100k-triangle last: no flipped triangle, D_angle and D_area <= 2.02, area error <= 1 %;
//  - the files of the output contract and the report.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "engine/mold/outline_alignment.hpp"
#include "engine/scan/scan_outputs.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

class ScanPipeline : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = lastcut::test::make_temp_dir("scan");
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static fs::path scan_of(const std::string& name, const LastParams& params) {
    const fs::path path = dir_ / (name + ".stl");
    write_stl_binary(path, generate_last(params).mesh);
    return path;
  }
  static inline fs::path dir_;
};

const SegmentResult& segment_named(const ScanResult& result, const std::string& name) {
  for (const auto& segment : result.segments)
    if (segment.name == name) return segment;
  throw EngineError("no segment " + name);
}

// Issue 2: two scans of one last (another pose, 0.2 mm noise with another seed, 16k against 24k
// triangles, 3 holes) give molds whose outlines agree within 1 mm after rigid alignment, half the
// thesis's 2 mm tolerance for a mold corner. Three lasts (sizes, both feet), not one lucky pair;
// bench/segment/repeatability_bench measures 12 more pairs (docs/benchmarks-segment.md).
struct RepeatCase {
  int eu_size;
  FootSide side;
  std::uint64_t seed;
};

TEST_F(ScanPipeline, TwoScansOfOneLastGiveTheSameMoldsWithin1mm) {
  for (const RepeatCase& c : {RepeatCase{42, FootSide::Left, 11}, RepeatCase{38, FootSide::Right, 21},
                              RepeatCase{45, FootSide::Left, 31}}) {
    SCOPED_TRACE("EU " + std::to_string(c.eu_size) + (c.side == FootSide::Left ? " left" : " right"));
    LastParams first = LastParams::for_eu_size(c.eu_size, c.side);
    first.noise_mm = 0.2;
    first.random_pose = true;
    first.holes = 3;
    first.target_triangles = 16000;
    first.seed = c.seed;
    LastParams second = first;
    second.target_triangles = 24000;
    second.seed = c.seed + 1;
    const ScanResult a = scan_to_molds(scan_of("first", first), {});
    const ScanResult b = scan_to_molds(scan_of("second", second), {});
    ASSERT_EQ(a.side, c.side);
    ASSERT_EQ(b.side, c.side);
    for (const std::string name : {"medial", "lateral"}) {
      const Mold& mold_a = segment_named(a, name).mold;
      const Mold& mold_b = segment_named(b, name).mold;
      ASSERT_EQ(mold_a.marks.size(), 4u) << name;
      const RigidTransform2 alignment = align_molds(mold_b, mold_a);
      const double distance_mm = hausdorff_distance_mm(transformed(mold_b.outline, alignment), mold_a.outline);
      RecordProperty("EU" + std::to_string(c.eu_size) + "_" + name + "_hausdorff_mm", std::to_string(distance_mm));
      EXPECT_LT(distance_mm, 1.0) << name;
      // Not trivially small either: the scans really differ.
      EXPECT_GT(distance_mm, 0.01) << name;
    }
  }
}

TEST_F(ScanPipeline, A100kTriangleLastFlattensWithinTheThesisBounds) {
  LastParams params = LastParams::for_eu_size(42, FootSide::Right);
  params.target_triangles = 100000;
  params.seed = 5;
  const ScanResult result = scan_to_molds(scan_of("big", params), {});
  ASSERT_EQ(result.segments.size(), 2u);
  EXPECT_EQ(result.side, FootSide::Right);
  int triangles = 0;
  for (const auto& segment : result.segments) {
    const DistortionMeasures& m = segment.measures;
    triangles += segment.mesh3d.triangle_count();
    EXPECT_EQ(m.flipped_triangles, 0) << segment.name;
    EXPECT_LE(m.D_angle, 2.02) << segment.name;
    EXPECT_LE(m.D_area, 2.02) << segment.name;
    EXPECT_LE(std::abs(m.area_error_pct), 1.0) << segment.name;
    EXPECT_EQ(segment.UV.rows(), segment.mesh3d.vertex_count());
  }
  EXPECT_GT(triangles, 60000);  // the halves are most of the last (the sole and top are not molds)
}

TEST_F(ScanPipeline, WritesTheContractFilesAndReport) {
  LastParams params = LastParams::for_eu_size(38, FootSide::Left);
  params.target_triangles = 8000;
  ScanOptions options;
  options.mold.allowance_mm = 3.0;
  const ScanResult result = scan_to_molds(scan_of("small", params), options);
  const fs::path out = dir_ / "out";
  write_scan_outputs(result, out);
  for (const auto& segment : result.segments) {
    for (const char* suffix : {"-3d.obj", "-flat.obj", ".dxf", ".svg"})
      EXPECT_TRUE(fs::exists(out / (segment.name + suffix))) << segment.name << suffix;
    const Mold back = read_mold_dxf(out / (segment.name + ".dxf"));
    EXPECT_EQ(back.outline.points.size(), segment.mold.outline.points.size());
    // Heel left, toe right.
    std::map<std::string, Point2> marks;
    for (const auto& mark : back.marks) marks[mark.name] = mark.position_mm;
    ASSERT_TRUE(marks.count("toe") && marks.count("heel")) << segment.name;
    EXPECT_GT(marks["toe"].x() - marks["heel"].x(), 150.0) << segment.name;
  }
  EXPECT_FALSE(fs::exists(out / "report.json.partial"));
  const nlohmann::json report = scan_report_json(result);
  EXPECT_EQ(report["units"], "mm");
  EXPECT_EQ(report["side"], "left");
  ASSERT_EQ(report["segments"].size(), 2u);
  for (const char* field : {"name", "triangles", "flipped", "D_angle", "D_area", "area_3d_mm2", "area_2d_mm2",
                            "boundary_3d_mm", "boundary_2d_mm", "max_stretch", "seconds_flatten"})
    EXPECT_TRUE(report["segments"][0].contains(field)) << field;
}

TEST_F(ScanPipeline, RefusesAnOpenPatchUnlessAskedNotToSegment) {
  LastParams params = LastParams::for_eu_size(38, FootSide::Left);
  params.target_triangles = 8000;
  const ScanResult last = scan_to_molds(scan_of("for-patch", params), {});
  const fs::path patch = dir_ / "medial-patch.obj";
  write_obj(patch, segment_named(last, "medial").mesh3d);
  try {
    scan_to_molds(patch, {});
    FAIL() << "an open patch was segmented";
  } catch (const EngineError& error) {
    EXPECT_NE(std::string(error.what()).find("not a closed last"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("--no-segment"), std::string::npos) << error.what();
  }
  ScanOptions no_segment;
  no_segment.segment = false;
  const ScanResult flat = scan_to_molds(patch, no_segment);
  ASSERT_EQ(flat.segments.size(), 1u);
  EXPECT_EQ(flat.segments[0].name, "patch");
  EXPECT_FALSE(flat.side.has_value());
  // The same half flattened again gives the same mold shape.
  const double distance_mm = hausdorff_distance_mm(
      transformed(flat.segments[0].mold.outline, align_molds(flat.segments[0].mold, segment_named(last, "medial").mold)),
      segment_named(last, "medial").mold.outline);
  EXPECT_LT(distance_mm, 0.1);
  // And a whole last is not a patch.
  EXPECT_THROW(scan_to_molds(dir_ / "for-patch.stl", no_segment), EngineError);
}

// A 10 x 10 cell grid patch, 80 x 60 mm, gently curved, with the middle vertex at height spike_mm.
TriMesh grid_patch(double spike_mm) {
  constexpr int n = 10;
  TriMesh patch;
  patch.V.resize((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = 8.0 * i, y = 6.0 * j;
      patch.V.row(j * (n + 1) + i) << x, y, 0.004 * (x - 40) * (x - 40) + 0.01 * (y - 30) * (y - 30);
    }
  patch.V((n / 2) * (n + 1) + n / 2, 2) = spike_mm;
  patch.F.resize(2 * n * n, 3);
  for (int j = 0, f = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      patch.F.row(f++) << a, b, d;
      patch.F.row(f++) << a, d, c;
    }
  return patch;
}

TEST_F(ScanPipeline, APatchWithAStrayPointIsRefusedAndOneWithASpikeWarns) {
  ScanOptions no_segment;
  no_segment.segment = false;
  no_segment.read.unit = LengthUnit::Millimetre;
  const fs::path plain = dir_ / "grid.obj";
  write_obj(plain, grid_patch(0.0));
  const ScanResult fine = scan_to_molds(plain, no_segment);
  EXPECT_TRUE(fine.warnings.empty()) << fine.warnings.front();

  // Found by fuzzing (scan_patch): one vertex of a half moved to 161 m gave a "mold" with area -99 %.
  const fs::path stray = dir_ / "grid-stray.obj";
  write_obj(stray, grid_patch(161271.0));
  try {
    scan_to_molds(stray, no_segment);
    FAIL() << "a patch 161 m tall was flattened";
  } catch (const EngineError& error) {
    EXPECT_EQ(std::string(error.what()),
              "not a patch of a last: 80 x 60 x 161271 mm (at most 1000 mm across; a wrong length unit, or a stray "
              "point far off the surface?)");
  }

  // A spike the size check lets through: the mold is made, and the operator is told to look at it.
  const fs::path spike = dir_ / "grid-spike.obj";
  write_obj(spike, grid_patch(400.0));
  const ScanResult spiked = scan_to_molds(spike, no_segment);
  ASSERT_EQ(spiked.warnings.size(), 1u);
  EXPECT_NE(spiked.warnings[0].find("patch: the mold's area is "), std::string::npos) << spiked.warnings[0];
  EXPECT_NE(spiked.warnings[0].find("smaller than the surface's"), std::string::npos) << spiked.warnings[0];
}

}  // namespace
}  // namespace lastcut
