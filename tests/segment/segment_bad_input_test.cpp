// Inputs the segmentation must refuse with one readable line instead of returning nonsense.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/segment/segment_last.hpp"
#include "segment_test_support.hpp"

namespace lastcut {
namespace {

std::string error_of(const OrientedLast& last, const SegmentOptions& options = {}) {
  try {
    segment_last(last, options);
  } catch (const EngineError& error) {
    return error.what();
  }
  return "";
}

TEST(SegmentBadInput, EmptyMeshIsRefused) {
  OrientedLast last;
  last.mesh.V.resize(0, 3);
  last.mesh.F.resize(0, 3);
  last.side = FootSide::Left;
  EXPECT_NE(error_of(last), "");
}

TEST(SegmentBadInput, UpsideDownHemisphereHasNoSole) {
  OrientedLast last;
  last.side = FootSide::Right;
  last.mesh = test::uv_sphere(40.0, 20, 30);
  // Keep only the upper half: nothing faces down.
  std::vector<int> lower;
  for (Eigen::Index v = 0; v < last.mesh.V.rows(); ++v)
    if (last.mesh.V(v, 2) < 5.0) lower.push_back(static_cast<int>(v));
  last.mesh = test::without_faces_around(last.mesh, lower);
  EXPECT_NE(error_of(last).find("faces down"), std::string::npos) << error_of(last);
}

TEST(SegmentBadInput, BadOptionsAreRefused) {
  OrientedLast last;
  last.mesh = test::uv_sphere(40.0, 20, 30);
  last.side = FootSide::Left;
  SegmentOptions options;
  options.sole_angle_rad = 0.5;
  EXPECT_NE(error_of(last, options), "");
  options = {};
  options.smoothing_passes = -1;
  EXPECT_NE(error_of(last, options), "");
  options = {};
  options.plane_t = 0.7;
  EXPECT_NE(error_of(last, options), "");
  options = {};
  options.feather_height_mm = 0.0;
  EXPECT_NE(error_of(last, options).find("feather line height"), std::string::npos) << error_of(last, options);
  options = {};
  options.rim_depth_mm = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_of(last, options).find("top rim depth"), std::string::npos) << error_of(last, options);
}

// A hole larger than the fill limit in a side wall leaves that half with two boundary loops: the
// operator must hear about the hole, not get a mold with a hole in it.
TEST(SegmentBadInput, LargeHoleInTheSideIsReported) {
  LastParams params = LastParams::for_eu_size(40, FootSide::Left);
  params.target_triangles = 12000;
  OrientedLast last;
  last.mesh = generate_last(params).mesh;
  last.side = FootSide::Left;
  last.scan_to_canonical = Eigen::Affine3d::Identity();
  const Eigen::Vector3d centre(0.55 * params.length_mm, 0.0, 35.0);
  std::vector<int> removed;  // vertices of the lateral (+Y) wall within 12 mm of a point at mid height
  const double wall_y = last.mesh.V.col(1).maxCoeff();
  for (Eigen::Index v = 0; v < last.mesh.V.rows(); ++v) {
    const Eigen::Vector3d p = last.mesh.V.row(v);
    if (p.y() > 0.0 && (Eigen::Vector2d(p.x(), p.z()) - Eigen::Vector2d(centre.x(), centre.z())).norm() < 12.0 &&
        p.y() > wall_y - 30.0)
      removed.push_back(static_cast<int>(v));
  }
  ASSERT_GT(removed.size(), 10u);
  last.mesh = test::without_faces_around(last.mesh, removed);
  const std::string error = error_of(last);
  EXPECT_NE(error.find("lateral half is not a single sheet"), std::string::npos) << error;
}

TEST(SegmentBadInput, ExpertSplitOptionsOutsideTheirRangeAreRefused) {
  auto circle = [](double cx, double z, double r, int count) {
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < count; ++i)
      points.emplace_back(cx + r * std::cos(0.1 * i * 3.14159265), r * std::sin(0.1 * i * 3.14159265), z);
    return points;
  };
  const std::vector<Eigen::Vector3d> lower = circle(100.0, 0.0, 100.0, 20), upper = circle(90.0, 120.0, 30.0, 20);
  for (auto change : {+[](ExpertSplitOptions& o) { o.second_toe_fraction = 0.0; },
                      +[](ExpertSplitOptions& o) { o.second_toe_fraction = 1.5; },
                      +[](ExpertSplitOptions& o) { o.toe_section_fraction = 1.0; },
                      +[](ExpertSplitOptions& o) { o.heel_arc_drop_mm = -1.0; }}) {
    ExpertSplitOptions options;
    change(options);
    EXPECT_THROW(expert_split_plane(lower, upper, options, FootSide::Left), EngineError);
  }
  EXPECT_NO_THROW(expert_split_plane(lower, upper, ExpertSplitOptions{}, FootSide::Left));
}

}  // namespace
}  // namespace lastcut
