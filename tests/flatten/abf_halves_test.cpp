// ABF++ on bigger meshes: the exactly developable cylinder and cone patches of ~50k triangles become their
// known development, and both halves of a generated last go through the scan pipeline flip-free with a
// valid mold.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "engine/flatten/flatten.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/mold/outline_geometry.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "tests/flatten/flatten_fixtures.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

void expect_developed(const testing::DevelopablePatch& patch) {
  ASSERT_GE(patch.mesh.triangle_count(), 45000);
  FlattenOptions options;
  options.method = FlattenMethod::Abf;
  const FlattenResult result = flatten(patch.mesh, options);
  const DistortionMeasures d = measure_distortion(patch.mesh, result.UV);
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.flipped_triangles, 0);
  EXPECT_EQ(d.flipped_triangles, 0);
  EXPECT_GE(d.D_angle, 2.0);
  EXPECT_LE(d.D_angle, 2.001);
  EXPECT_GE(d.D_area, 2.0);
  EXPECT_LE(d.D_area, 2.001);
  EXPECT_LE(testing::max_distance_after_rigid_alignment(result.UV, patch.development), 0.01);
  EXPECT_TRUE(result.notes.empty()) << result.notes.front();
  std::printf("Newton iterations %d, D_angle %.6f, D_area %.6f, %.3f s\n", result.iterations, d.D_angle, d.D_area,
              result.seconds_total);
}

TEST(AbfDevelopable, CylinderPatchBecomesItsDevelopment) {
  expect_developed(testing::cylinder_patch(60.0, 150.0, 200.0, 250, 100));
}

TEST(AbfDevelopable, ConePatchBecomesItsDevelopment) {
  expect_developed(testing::cone_patch(30.0, 200.0, 40.0, 180.0, 250, 100));
}

TEST(AbfHalves, GeneratedLastHalvesAreFlipFreeWithValidMolds) {
  const test::TempDir folder("abf-halves");
  const fs::path scan = folder / "last.stl";
  LastParams params = LastParams::for_eu_size(42, FootSide::Left);
  params.target_triangles = 60000;
  write_stl_binary(scan, generate_last(params).mesh);
  ScanOptions options;
  options.flatten.method = FlattenMethod::Abf;
  const ScanResult result = scan_to_molds(scan, options);
  ASSERT_EQ(result.segments.size(), 2u);
  for (const SegmentResult& segment : result.segments) {
    SCOPED_TRACE(segment.name);
    const DistortionMeasures& d = segment.measures;
    EXPECT_EQ(segment.flatten.flipped_triangles, 0);
    EXPECT_EQ(d.flipped_triangles, 0);
    EXPECT_TRUE(segment.flatten.converged);
    for (const std::string& note : segment.flatten.notes) std::printf("%s note: %s\n", segment.name.c_str(), note.c_str());
    // A generated half is nearly developable: angles kept, areas nearly so.
    EXPECT_LT(d.D_angle, 2.01);
    EXPECT_LT(d.D_area, 2.05);
    EXPECT_NEAR(d.area_error_pct, 0.0, 1e-6);
    // The mold: a simple counter-clockwise outline enclosing the flattened area (within the simplification),
    // with the notches of the landmarks.
    ASSERT_GE(segment.mold.outline.points.size(), 3u);
    EXPECT_TRUE(is_simple(segment.mold.outline));
    EXPECT_NEAR(signed_area(segment.mold.outline), d.area_2d_mm2, 0.005 * d.area_2d_mm2);
    EXPECT_FALSE(segment.mold.marks.empty());
    std::printf("%s: %d triangles, Newton iterations %d, D_angle %.5f, D_area %.5f, boundary error %.2f %%, %.3f s\n",
                segment.name.c_str(), segment.mesh3d.triangle_count(), segment.flatten.iterations, d.D_angle,
                d.D_area, d.boundary_error_pct, segment.flatten.seconds_total);
  }
}

}  // namespace
}  // namespace lastcut
