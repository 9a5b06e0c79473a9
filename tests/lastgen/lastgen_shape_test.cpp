// The generated last is a valid, realistic last: closed and outward, the size the parameters ask
// for, mirror-symmetric between feet, with a flat-ish sole, a flat top cut and an instep facing
// up and forward. Small meshes (a few thousand triangles) keep the suite fast.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/lastgen/last_shape.hpp"
#include "mesh_checks.hpp"

namespace lastcut {
namespace {

constexpr int kTriangles = 5000;

LastParams small_params(FootSide side) {
  LastParams params;
  params.side = side;
  params.target_triangles = kTriangles;
  return params;
}

// Generated on first use: CTest runs each test in its own process, so a test pays only for the
// lasts it looks at.
const GeneratedLast& right_last() {
  static const GeneratedLast last = generate_last(small_params(FootSide::Right));
  return last;
}
const GeneratedLast& left_last() {
  static const GeneratedLast last = generate_last(small_params(FootSide::Left));
  return last;
}

class GeneratedLastTest : public ::testing::Test {};

// Extent of the vertices in `axis` among those that pass `keep` (mm): {min, max}.
template <typename Keep>
Eigen::Vector2d extent(const TriMesh& mesh, int axis, Keep keep) {
  Eigen::Vector2d range(std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest());
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    const Eigen::Vector3d p = mesh.V.row(v);
    if (!keep(p)) continue;
    range(0) = std::min(range(0), p(axis));
    range(1) = std::max(range(1), p(axis));
  }
  return range;
}

TEST_F(GeneratedLastTest, IsAClosedOutwardTwoManifoldSphere) {
  for (const GeneratedLast* last : {&right_last(), &left_last()}) {
    const test::EdgeCensus census = test::edge_census(last->mesh);
    EXPECT_EQ(census.boundary_edges, 0);
    EXPECT_EQ(census.non_manifold_edges, 0);
    EXPECT_EQ(census.inconsistent_edges, 0);
    EXPECT_EQ(test::euler_characteristic(last->mesh), 2);
    EXPECT_GT(test::signed_volume_mm3(last->mesh), 0.9e6);  // a 270 mm last holds about 1.2 litres
    EXPECT_LT(test::signed_volume_mm3(last->mesh), 1.6e6);
    EXPECT_TRUE(last->canonical_to_scan.isApprox(Eigen::Affine3d::Identity()));
  }
}

TEST_F(GeneratedLastTest, HasTheRequestedTriangleCountAndNoSlivers) {
  EXPECT_NEAR(right_last().mesh.triangle_count(), kTriangles, 2);
  EXPECT_GT(test::worst_triangle_quality(right_last().mesh), 0.3);
  const Eigen::VectorXd areas = triangle_areas(right_last().mesh);
  EXPECT_LT(areas.maxCoeff() / areas.minCoeff(), 8.0);  // roughly uniform sizes
}

TEST_F(GeneratedLastTest, DimensionsMatchTheParameters) {
  const LastParams p = small_params(FootSide::Right);
  const TriMesh& mesh = right_last().mesh;
  const Eigen::Vector3d size = bounding_box_size(mesh);
  EXPECT_NEAR(size.x(), p.length_mm, 0.01 * p.length_mm);
  EXPECT_NEAR(size.y(), p.ball_width_mm, 0.02 * p.ball_width_mm);
  EXPECT_NEAR(mesh.V.col(0).minCoeff(), 0.0, 1.0);           // heel back at x = 0
  EXPECT_NEAR(mesh.V.col(2).minCoeff(), 0.0, 0.05);          // ball tread on the ground
  const double L = p.length_mm;
  const Eigen::Vector2d heel_seat = extent(mesh, 2, [&](const Eigen::Vector3d& q) { return q.x() > 0.08 * L && q.x() < 0.15 * L; });
  EXPECT_NEAR(heel_seat(0), p.heel_height_mm, 0.5);
  const Eigen::Vector2d heel = extent(mesh, 1, [&](const Eigen::Vector3d& q) {
    return q.x() > 0.12 * L && q.x() < 0.22 * L && q.z() < p.heel_height_mm + 15.0;
  });
  EXPECT_NEAR(heel(1) - heel(0), p.heel_width_mm, 0.06 * p.heel_width_mm);
  const Eigen::Vector2d toe = extent(mesh, 2, [&](const Eigen::Vector3d& q) { return q.x() > 0.985 * L; });
  EXPECT_GT(toe(0), 0.6 * p.toe_spring_mm);
  EXPECT_LT(toe(0), p.toe_spring_mm + 6.0);
  EXPECT_GT(size.z(), p.heel_height_mm + p.top_height_mm - 1.0);
  EXPECT_LT(size.z(), p.heel_height_mm + p.top_height_mm + 6.0);
}

TEST_F(GeneratedLastTest, ToeSpringAndHeelHeightMoveTheSole) {
  LastParams flat = small_params(FootSide::Right), sprung = flat;
  flat.toe_spring_mm = 4.0;
  flat.heel_height_mm = 10.0;
  sprung.toe_spring_mm = 20.0;
  sprung.heel_height_mm = 40.0;
  const TriMesh a = generate_last(flat).mesh, b = generate_last(sprung).mesh;
  const double L = flat.length_mm;
  auto near_tip = [&](const Eigen::Vector3d& q) { return q.x() > 0.985 * L; };
  auto heel_seat = [&](const Eigen::Vector3d& q) { return q.x() > 0.08 * L && q.x() < 0.15 * L; };
  EXPECT_NEAR(extent(b, 2, near_tip)(0) - extent(a, 2, near_tip)(0), 16.0, 4.0);
  EXPECT_NEAR(extent(b, 2, heel_seat)(0) - extent(a, 2, heel_seat)(0), 30.0, 0.5);
  EXPECT_NEAR(extent(a, 2, [](const Eigen::Vector3d&) { return true; })(0), 0.0, 0.05);
  EXPECT_NEAR(extent(b, 2, [](const Eigen::Vector3d&) { return true; })(0), 0.0, 0.05);
}

TEST_F(GeneratedLastTest, LeftIsTheMirrorImageOfRight) {
  ASSERT_EQ(left_last().mesh.V.rows(), right_last().mesh.V.rows());
  ASSERT_EQ(left_last().mesh.F.rows(), right_last().mesh.F.rows());
  Eigen::MatrixXd mirrored = right_last().mesh.V;
  mirrored.col(1) *= -1.0;
  EXPECT_TRUE(left_last().mesh.V.isApprox(mirrored, 1e-12));
  EXPECT_TRUE(left_last().mesh.F.col(0) == right_last().mesh.F.col(0));
  EXPECT_TRUE(left_last().mesh.F.col(1) == right_last().mesh.F.col(2));
  EXPECT_GT(test::signed_volume_mm3(left_last().mesh), 0.0);
}

TEST_F(GeneratedLastTest, MedialSideHasTheToeTipAndTheForwardBallPoint) {
  for (const auto& [last, side] : {std::pair{&right_last(), FootSide::Right}, std::pair{&left_last(), FootSide::Left}}) {
    const TriMesh& mesh = last->mesh;
    const double medial = medial_y_sign(side);
    Eigen::Index tip = 0, medial_ball = 0, lateral_ball = 0;
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
      if (mesh.V(v, 0) > mesh.V(tip, 0)) tip = v;
      if (medial * mesh.V(v, 1) > medial * mesh.V(medial_ball, 1)) medial_ball = v;
      if (medial * mesh.V(v, 1) < medial * mesh.V(lateral_ball, 1)) lateral_ball = v;
    }
    EXPECT_GT(medial * mesh.V(tip, 1), 3.0) << "toe tip not shifted medially on the " << to_string(side) << " last";
    EXPECT_GT(mesh.V(medial_ball, 0), mesh.V(lateral_ball, 0) + 10.0) << "first metatarsal not ahead of the fifth";
    EXPECT_GT(mesh.V(medial_ball, 0), 0.62 * 270.0);
    EXPECT_LT(mesh.V(medial_ball, 0), 0.78 * 270.0);
  }
}

TEST_F(GeneratedLastTest, SoleFacesDownTopCutFacesUpInstepFacesUpAndForward) {
  const LastParams p = small_params(FootSide::Right);
  const LastShape shape(p);
  const TriMesh& mesh = right_last().mesh;
  const Eigen::MatrixXd normals = triangle_normals(mesh);
  const Eigen::VectorXd areas = triangle_areas(mesh);
  double sole_area = 0.0, top_area = 0.0, instep_area = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d centre = (mesh.V.row(mesh.F(f, 0)) + mesh.V.row(mesh.F(f, 1)) + mesh.V.row(mesh.F(f, 2))) / 3.0;
    const Eigen::Vector3d n = normals.row(f);
    if (centre.z() - shape.sole_z_mm(centre.x()) < 0.3) {
      EXPECT_LT(n.z(), -std::cos(M_PI / 4)) << "sole face at x = " << centre.x() << " not facing down";
      sole_area += areas(f);
    }
    if (centre.z() > shape.top_cut_z_mm(centre.x()) - 0.3) {
      EXPECT_GT(n.z(), 0.8) << "top cut face at x = " << centre.x() << " not facing up";
      if (n.dot(shape.top_cut_normal()) > 0.999) top_area += areas(f);
    }
    if (centre.x() > 0.5 * p.length_mm && centre.x() < 0.6 * p.length_mm && std::abs(centre.y()) < 10.0 && centre.z() > 40.0) {
      EXPECT_GT(n.z(), 0.3);
      EXPECT_GT(n.x(), 0.3);
      instep_area += areas(f);
    }
  }
  // The sole is most of the plan area; the flat top is the 35-45 x 80-100 mm cone cut.
  EXPECT_GT(sole_area, 0.5 * 0.7 * p.length_mm * p.ball_width_mm);
  EXPECT_GT(top_area, 0.7 * 35.0 * 80.0);
  EXPECT_LT(top_area, 45.0 * 100.0);
  EXPECT_GT(instep_area, 100.0);
}

TEST(LastParams, EuSizeSweepGivesPlausibleLasts) {
  double previous_volume = 0.0;
  for (const int size : {35, 38, 41, 44, 47}) {
    LastParams params = LastParams::for_eu_size(size, FootSide::Left);
    params.target_triangles = 3000;
    const TriMesh mesh = generate_last(params).mesh;
    const Eigen::Vector3d box = bounding_box_size(mesh);
    EXPECT_NEAR(box.x(), size * 20.0 / 3.0, 0.01 * box.x()) << "EU " << size;
    EXPECT_NEAR(box.y() / box.x(), 95.0 / 270.0, 0.01) << "EU " << size;
    EXPECT_EQ(test::edge_census(mesh).boundary_edges, 0) << "EU " << size;
    const double volume = test::signed_volume_mm3(mesh);
    EXPECT_GT(volume, previous_volume) << "EU " << size;
    previous_volume = volume;
  }
}

TEST(LastParams, ImpossibleParametersAreRefusedWithAReason) {
  EXPECT_THROW(LastParams::for_eu_size(34, FootSide::Left), EngineError);
  EXPECT_THROW(LastParams::for_eu_size(48, FootSide::Right), EngineError);
  LastParams params;
  params.length_mm = -5;
  try {
    generate_last(params);
    FAIL() << "negative length accepted";
  } catch (const EngineError& error) {
    EXPECT_NE(std::string(error.what()).find("length"), std::string::npos) << error.what();
  }
  params = LastParams{};
  params.target_triangles = 10;
  EXPECT_THROW(generate_last(params), EngineError);
  params = LastParams{};
  params.noise_mm = -1;
  EXPECT_THROW(generate_last(params), EngineError);
  params = LastParams{};
  params.ball_width_mm = 400;
  EXPECT_THROW(generate_last(params), EngineError);
}

}  // namespace
}  // namespace lastcut
