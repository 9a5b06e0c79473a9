// A derby's upper pieces cut from a scanned last (issue 34, point 3, "Pieces tile the upper"): a vamp
// line and a counter line drawn on a reference last, the lacing opening and the quarters' back seam cut
// along the centre seams, four labels. Transferred to the same last remeshed and posed, the pieces must
// cover the upper (the two halves' 3D area) within 0.1 % without overlapping, each must be a disk, and
// each flattens flip-free; D_area is no worse than the halves' for the pieces that do not wrap the toe.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <regex>
#include <tuple>

#include "engine/core/engine_error.hpp"
#include "engine/core/mesh_topology.hpp"
#include "engine/flatten/distortion.hpp"
#include "engine/flatten/flatten.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/mold/outline_geometry.hpp"
#include "engine/style/piece_mold.hpp"
#include "engine/style/piece_surface.hpp"
#include "engine/style/style_transfer.hpp"
#include "engine/style/upper_regions.hpp"
#include "tests/support/derby_style.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

ScanResult segmented(const TriMesh& mesh, const std::filesystem::path& file) {
  write_mesh(file, mesh);
  ScanOptions options;
  options.side = FootSide::Right;
  return scan_to_molds(file, options);
}

// One derby on one pair of lasts for every test: the scans take most of the time.
class UpperPieces : public ::testing::Test {
 protected:
  struct Derby {
    TriMesh reference_mesh;
    ScanResult reference, target;
    std::unique_ptr<StyleTransfer> transfer;
    TransferredCurve vamp, counter;
    std::vector<SeamCut> cuts;
    std::vector<PieceLabel> labels;
    std::array<const SegmentResult*, 2> halves{};
  };

  static void SetUpTestSuite() {
    static const test::TempDir dir("upper-pieces");
    derby_ = new Derby;
    Derby& d = *derby_;
    LastParams params = LastParams::for_eu_size(42, FootSide::Right);
    params.target_triangles = 40000;
    d.reference_mesh = generate_last(params).mesh;
    d.reference = segmented(d.reference_mesh, dir / "reference.stl");
    params.target_triangles = 50000;
    params.random_pose = true;
    params.seed = 3;
    d.target = segmented(generate_last(params).mesh, dir / "posed.stl");
    d.transfer = std::make_unique<StyleTransfer>(d.reference, d.target);
    const test::TransferredDerby derby = test::transfer_derby(d.reference_mesh, *d.transfer);
    d.vamp = derby.lines[0];
    d.counter = derby.lines[1];
    d.cuts = derby.cuts;
    d.labels = derby.labels;
    d.halves = {&d.target.segments[0], &d.target.segments[1]};
  }
  static void TearDownTestSuite() { delete derby_; }
  static inline Derby* derby_ = nullptr;
};

TEST_F(UpperPieces, DerbyPiecesTileTheUpperAndFlattenEachAsADisk) {
  const Derby& d = *derby_;
  ASSERT_TRUE(std::isfinite(d.cuts[0].from_share) && std::isfinite(d.cuts[1].from_share));
  const auto& halves = d.halves;
  ASSERT_EQ(halves[0]->name, "medial");
  const std::vector<PieceRegion> regions = piece_regions(halves, {d.vamp, d.counter}, d.labels, d.cuts);
  ASSERT_EQ(regions.size(), 4u);

  double upper_mm2 = 0, worst_half_D_area = 0;
  for (const SegmentResult* half : halves) {
    upper_mm2 += half->measures.area_3d_mm2;
    worst_half_D_area = std::max(worst_half_D_area, half->measures.D_area);
  }
  double pieces_mm2 = 0;
  for (const PieceRegion& region : regions) {
    const PieceSurface piece = cut_piece_surface(halves, region);
    pieces_mm2 += piece.area_mm2;
    const MeshTopology topology = build_mesh_topology(piece.mesh.F, piece.mesh.V.rows());
    EXPECT_EQ(topology.boundary_loops.size(), 1u) << piece.name << " is not a disk";
    const FlattenResult flat = flatten(piece.mesh, topology);
    const DistortionMeasures measures = measure_distortion(piece.mesh, flat.UV, topology);
    std::printf("%-16s %2zu parts %6ld triangles (%d clipped) %8.1f mm2  D_angle %.4f D_area %.4f flipped %d\n",
                piece.name.c_str(), region.parts.size(), static_cast<long>(piece.mesh.F.rows()), piece.clipped_triangles,
                piece.area_mm2, measures.D_angle, measures.D_area, measures.flipped_triangles);
    EXPECT_EQ(measures.flipped_triangles, 0) << piece.name;
    EXPECT_TRUE(flat.converged) << piece.name;
    // A piece on one half is part of a nearly developable surface and flattens at least as well. One that
    // spans both halves may be more curved than either: the vamp wraps the toe, measured D_area 2.0011
    // against the halves' 2.0002 (Nov 29); such a piece gets 0.002 more.
    const double spanning_allowance = region.parts.size() == 1 ? 0.0 : 0.002;
    EXPECT_LE(measures.D_area, worst_half_D_area + spanning_allowance) << piece.name;
  }
  std::printf("upper %.1f mm2, pieces %.1f mm2 (%+.4f %%)\n", upper_mm2, pieces_mm2, 100 * (pieces_mm2 - upper_mm2) / upper_mm2);
  EXPECT_NEAR(pieces_mm2, upper_mm2, 1e-3 * upper_mm2);  // tiles the upper: nothing missing, nothing twice
}

// Measured on the cut outline, independently of how it was grown: the points of the middle third of a
// stretch of the net lie their edge's allowance inside the cut outline.
TEST_F(UpperPieces, EachEdgeCarriesItsAllowance) {
  const Derby& d = *derby_;
  const std::vector<PieceRegion> regions = piece_regions(d.halves, {d.vamp, d.counter}, d.labels, d.cuts);
  const PieceEdgeCurves curves = piece_edge_curves(d.halves, {d.vamp, d.counter}, d.target.scan_to_canonical);
  std::map<std::string, int> stretches_measured;
  for (const PieceRegion& region : regions) {
    const PieceSurface piece = cut_piece_surface(d.halves, region);
    const PieceMold mold =
        make_piece_mold(piece, curves, [&](const PieceEdgeSource& source) { return test::derby_allowance(piece.name, source); });
    EXPECT_GE(mold.edges.size(), 2u) << piece.name;
    for (const PieceMoldEdge& edge : mold.edges) {
      double length_mm = 0;
      for (std::size_t i = 1; i < edge.net_points.size(); ++i) length_mm += (edge.net_points[i] - edge.net_points[i - 1]).norm();
      if (length_mm < 3 * edge.allowance_mm + 15) continue;  // too short to have a middle away from the corners
      double walked = 0;
      std::vector<double> distances;
      for (std::size_t i = 1; i < edge.net_points.size(); ++i) {
        walked += (edge.net_points[i] - edge.net_points[i - 1]).norm();
        if (walked < length_mm / 3 || walked > 2 * length_mm / 3) continue;
        distances.push_back(closest_outline_point(mold.mold.outline, edge.net_points[i]).distance_mm);
      }
      ASSERT_FALSE(distances.empty());
      std::sort(distances.begin(), distances.end());
      const std::string where = piece.name + " " + to_string(edge.source, {"vamp", "counter"});
      // Nothing cuts into the margin; typically exactly the allowance; at a kink where the net turns
      // away from the cut line (concave) the corner of the offset lies d / cos(turn / 2) away.
      EXPECT_GE(distances.front(), edge.allowance_mm - 0.03) << where;
      EXPECT_NEAR(distances[distances.size() / 2], edge.allowance_mm, 0.02) << where;
      EXPECT_LE(distances.back(), edge.allowance_mm + 0.2) << where;
      ++stretches_measured[piece.name];
    }
  }
  EXPECT_EQ(stretches_measured.size(), 4u);
}

// Seams match (issue 34): the two pieces sewn along a line or a cut seam should have stretches of the same
// length in their flattenings, or the closing room cannot stitch them mark to mark. Measured on each piece's net
// outline: the vamp line (vamp against both quarters), the counter line (counter against both quarters),
// the quarters' back seam and the lacing opening's two sides.
TEST_F(UpperPieces, SewnEdgesHaveTheSameLengthOnBothPieces) {
  const Derby& d = *derby_;
  const std::vector<PieceRegion> regions = piece_regions(d.halves, {d.vamp, d.counter}, d.labels, d.cuts);
  const PieceEdgeCurves curves = piece_edge_curves(d.halves, {d.vamp, d.counter}, d.target.scan_to_canonical);
  // length[piece][what the stretch lies on]
  std::map<std::string, std::map<std::string, double>> length, length_3d;
  for (const PieceRegion& region : regions) {
    const PieceSurface piece = cut_piece_surface(d.halves, region);
    const PieceMold mold = make_piece_mold(piece, curves, [](const PieceEdgeSource&) { return 0.0; });
    for (const std::string& note : mold.flatten.notes) std::printf("%-16s %s\n", piece.name.c_str(), note.c_str());
    for (const PieceMoldEdge& edge : mold.edges)
      for (std::size_t i = 1; i < edge.net_points.size(); ++i)
        length[piece.name][to_string(edge.source, {"vamp", "counter"})] += (edge.net_points[i] - edge.net_points[i - 1]).norm();
    for (const PieceMoldEdge& edge : mold.edges) length_3d[piece.name][to_string(edge.source, {"vamp", "counter"})] += edge.length_3d_mm;
  }
  const auto both_quarters = [&](const std::string& on) { return length["medial quarter"][on] + length["lateral quarter"][on]; };
  for (const auto& [piece, stretches] : length)
    for (const auto& [on, mm] : stretches)
      std::printf("%-16s %-13s flat %7.2f mm, on the last %7.2f mm (%+.2f %%)\n", piece.c_str(), on.c_str(), mm, length_3d[piece][on],
                  100 * (mm - length_3d[piece][on]) / length_3d[piece][on]);
  const std::vector<std::tuple<std::string, double, double>> seams = {
      {"vamp line", length["vamp"]["line vamp"], both_quarters("line vamp")},
      {"counter line", length["counter"]["line counter"], both_quarters("line counter")},
      {"back seam", length["medial quarter"]["back seam"], length["lateral quarter"]["back seam"]},
      {"lacing opening", length["medial quarter"]["front seam"], length["lateral quarter"]["front seam"]}};
  // Issue 34 asks for 0.5 mm. Each piece's plain ARAP flattening changed its stretches' lengths by up to
  // 1.6 %, differently on the two sides (vamp line +2.61 mm, counter line -1.53): the sewn stretches are
  // now held at their 3D length (arap_held_lengths.hpp). Measured Nov 29: +0.00, -0.05, -0.00, -0.01 mm.
  constexpr double kSeamMismatch_mm = 0.5;
  for (const auto& [seam, one, other] : seams) {
    std::printf("%-15s %7.2f mm against %7.2f mm (%+.2f)\n", seam.c_str(), one, other, one - other);
    EXPECT_GT(one, 20) << seam;
    EXPECT_NEAR(one, other, kSeamMismatch_mm) << seam;
  }
}

// Refusals name what is wrong in one line.
TEST_F(UpperPieces, ARegionWithoutALabelIsRefused) {
  const Derby& d = *derby_;
  std::vector<PieceLabel> labels = d.labels;
  labels.erase(labels.begin() + 1);  // no counter label
  try {
    piece_regions(d.halves, {d.vamp, d.counter}, labels, d.cuts);
    FAIL() << "no error";
  } catch (const EngineError& error) {
    const std::regex expected(R"(the region at the (medial|lateral) forme \(-?[0-9]+, -?[0-9]+\) mm has no piece: )"
                              "a label is missing or a line does not reach an edge");
    EXPECT_TRUE(std::regex_match(std::string(error.what()), expected)) << error.what();
  }
}

TEST_F(UpperPieces, TwoLabelsInOneRegionAreRefused) {
  const Derby& d = *derby_;
  try {
    piece_regions(d.halves, {d.vamp}, d.labels, d.cuts);  // the counter line left out
    FAIL() << "no error";
  } catch (const EngineError& error) {
    EXPECT_STREQ(error.what(), "pieces counter and medial quarter lie in one region: a style line between them is missing "
                               "or does not reach an edge");
  }
}

}  // namespace
}  // namespace lastcut
