// A symmetric (straight) last through the whole pipeline: named left or right it gives medial and
// lateral molds, the two assignments mirror each other (left's medial half is right's lateral half,
// the -Y one); unnamed it gives side_a (+Y) and side_b (-Y) molds and the warning, not a failure.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/scan/scan_outputs.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

class ScanSide : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = lastcut::test::make_temp_dir("scan-side");
    LastParams params = LastParams::for_eu_size(40, FootSide::Left);
    params.symmetric = true;
    params.target_triangles = 20000;
    params.random_pose = true;
    write_stl_binary(dir_ / "straight.stl", generate_last(params).mesh);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static std::map<std::string, const SegmentResult*> by_name(const ScanResult& result) {
    std::map<std::string, const SegmentResult*> halves;
    for (const SegmentResult& segment : result.segments) halves[segment.name] = &segment;
    return halves;
  }
  static double mean_y_mm(const TriMesh& mesh) { return mesh.V.col(1).mean(); }

  static ScanResult run(std::optional<FootSide> side) {
    ScanOptions options;
    options.side = side;
    return scan_to_molds(dir_ / "straight.stl", options);
  }

  static inline fs::path dir_;
};

TEST_F(ScanSide, NamedLeftAndRightGiveMedialAndLateralMoldsThatMirror) {
  const ScanResult left = run(FootSide::Left), right = run(FootSide::Right);
  ASSERT_EQ(left.side, FootSide::Left);
  ASSERT_EQ(right.side, FootSide::Right);
  EXPECT_TRUE(left.warnings.empty());
  EXPECT_TRUE(right.warnings.empty());
  const auto l = by_name(left), r = by_name(right);
  ASSERT_EQ(l.size(), 2u);
  ASSERT_TRUE(l.count("medial") && l.count("lateral") && r.count("medial") && r.count("lateral"));
  // Left: medial is -Y; right: medial is +Y (engine/core/foot_side.hpp).
  EXPECT_LT(mean_y_mm(l.at("medial")->mesh3d), -10.0);
  EXPECT_GT(mean_y_mm(r.at("medial")->mesh3d), 10.0);
  // The same scan, the same frame and the same split: each half is the other name's half of the other foot.
  for (const auto& [left_name, right_name] : {std::pair{"medial", "lateral"}, std::pair{"lateral", "medial"}}) {
    const SegmentResult& a = *l.at(left_name);
    const SegmentResult& b = *r.at(right_name);
    EXPECT_EQ(a.mesh3d.triangle_count(), b.mesh3d.triangle_count()) << left_name;
    EXPECT_NEAR(a.measures.area_3d_mm2, b.measures.area_3d_mm2, 1e-6 * a.measures.area_3d_mm2) << left_name;
    EXPECT_NEAR(mean_y_mm(a.mesh3d), mean_y_mm(b.mesh3d), 1e-6) << left_name;
    EXPECT_EQ(a.measures.flipped_triangles, 0);
  }
}

TEST_F(ScanSide, WithoutASideTheMoldsGetNeutralNamesAndTheWarning) {
  const ScanResult result = run(std::nullopt);
  EXPECT_FALSE(result.side.has_value());
  ASSERT_EQ(result.segments.size(), 2u);
  EXPECT_EQ(result.segments[0].name, "side_a");
  EXPECT_EQ(result.segments[1].name, "side_b");
  EXPECT_GT(mean_y_mm(result.segments[0].mesh3d), 10.0);   // +Y: on the left seen from above, toe away
  EXPECT_LT(mean_y_mm(result.segments[1].mesh3d), -10.0);
  for (const SegmentResult& segment : result.segments) EXPECT_EQ(segment.measures.flipped_triangles, 0);
  const std::string warning =
      "symmetric last: the side was not named, halves named side_a and side_b; give --side or the sidecar's side to "
      "name them medial/lateral";
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0], warning);
  const nlohmann::json report = write_scan_outputs(result, dir_ / "neutral");
  EXPECT_TRUE(report["side"].is_null());
  EXPECT_EQ(report["warnings"], nlohmann::json::array({warning}));
  EXPECT_TRUE(fs::exists(dir_ / "neutral" / "side_a.dxf"));
  EXPECT_TRUE(fs::exists(dir_ / "neutral" / "side_b.dxf"));
}

}  // namespace
}  // namespace lastcut
