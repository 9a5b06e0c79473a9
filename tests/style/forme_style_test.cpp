// A style drawn on the forme (issue 34, point 1): the forme's layout, and the shipped derby drawn on it
// and lifted back. The derby's lines were drawn in 3D (config/styles/derby/lines.obj) on the generated
// EU 42 right last, 40000 triangles; drawn on that last's forme (tests/support/derby_forme.hpp), read
// from a DXF and lifted onto the last, every point must lie within 0.1 mm of the 3D line it came from,
// measured against that polyline itself. Each refusal is checked word for word, its numbers computed
// here from the outline polygons.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <algorithm>
#include <memory>

#include "daemon/config/style_folder.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/style/forme_lift.hpp"
#include "tests/support/derby_forme.hpp"
#include "tests/support/style_line_geometry.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

const fs::path kDerby = fs::path(LASTCUT_SOURCE_DIR) / "config" / "styles" / "derby";

double distance_to_outline(const std::vector<Point2>& outline, const Point2& p) {
  double nearest = INFINITY;
  for (std::size_t i = 0; i < outline.size(); ++i) nearest = std::min(nearest, distance_to_segment(p, outline[i], outline[(i + 1) % outline.size()]));
  return nearest;
}

// A 3D polyline as it lies on the last: sampled every 0.05 mm, each sample moved to the closest point of
// the last's surface. The derby's lines are plane sections with points 4.4 mm apart; their chords cut
// under the surface by up to 0.12 mm where it curves (round the heel) and 0.85 mm where they cut the
// rounded corner of the feather line to the sole, where the line on the upper ends.
test::Polyline on_surface(const test::Polyline& line, const TriMesh& last) {
  const SurfaceLocator locator(last.V, last.F);
  test::Polyline out;
  for (std::size_t i = 1; i < line.size(); ++i) {
    const int pieces = std::max(1, static_cast<int>(std::ceil((line[i] - line[i - 1]).norm() / 0.05)));
    for (int k = 0; k < pieces; ++k) {
      const SurfaceHit hit = locator.closest(line[i - 1] + (line[i] - line[i - 1]) * (static_cast<double>(k) / pieces));
      Eigen::Vector3d on = Eigen::Vector3d::Zero();
      for (int c = 0; c < 3; ++c) on += hit.barycentric(c) * last.V.row(last.F(hit.face, c)).transpose();
      out.push_back(on);
    }
  }
  return out;
}

std::string one_decimal(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", value);
  return text;
}

class FormeStyle : public ::testing::Test {
 protected:
  struct Shared {
    test::TempDir dir{"forme-style"};
    ScanResult reference;
    FormeLayout layout;
    std::unique_ptr<StyleTransfer> identity;
    daemon::StyleFolder derby;
    std::vector<test::Polyline> derby_on_surface;  // the derby's lines on the last, in the order of lines.obj
  };

  static void SetUpTestSuite() {
    shared_ = new Shared;
    Result<daemon::StyleFolder> derby = daemon::read_style_folder(kDerby);
    ASSERT_TRUE(derby) << derby.error();
    shared_->derby = *derby;
    const TriMesh last = generate_last(*derby->generated_reference).mesh;
    write_mesh(shared_->dir / "reference.stl", last);
    for (const StyleLine& line : derby->style.lines) shared_->derby_on_surface.push_back(on_surface(line.points_mm, last));
    ScanOptions options;
    options.side = derby->reference_side;
    shared_->reference = scan_to_molds(shared_->dir / "reference.stl", options);
    shared_->layout = forme_layout(shared_->reference);
    shared_->identity = std::make_unique<StyleTransfer>(shared_->reference, shared_->reference);
  }
  static void TearDownTestSuite() { delete shared_; }

  // The derby's lines and piece labels drawn on the forme.
  static std::pair<std::vector<test::DrawnPolyline>, std::vector<test::DrawnText>> derby_drawing() {
    std::vector<test::DrawnPolyline> lines;
    for (const StyleLine& line : shared_->derby.style.lines)
      for (test::DrawnPolyline& drawn : test::line_on_forme(*shared_->identity, shared_->layout, line)) lines.push_back(drawn);
    std::vector<test::DrawnText> texts;
    for (const StylePiece& piece : shared_->derby.style.pieces)
      texts.push_back({piece.name, test::point_on_forme(*shared_->identity, shared_->layout, piece.label_mm)});
    return {lines, texts};
  }

  static FormeDrawing read_drawing(const std::string& name, const std::vector<test::DrawnPolyline>& lines,
                                   const std::vector<test::DrawnText>& texts) {
    const fs::path file = shared_->dir / name;
    std::ofstream(file) << test::drawing_dxf(lines, texts);
    return read_forme_drawing(file);
  }

  static LiftedForme lift(const FormeDrawing& drawing) {
    return lift_forme_drawing(drawing, shared_->layout, shared_->reference.scan_to_canonical);
  }

  // What lifting the drawing refuses, or "" when it does not.
  static std::string refusal(const std::string& name, const std::vector<test::DrawnPolyline>& lines,
                             const std::vector<test::DrawnText>& texts) {
    try {
      lift(read_drawing(name, lines, texts));
    } catch (const EngineError& error) {
      return error.what();
    }
    return "";
  }

  static const FormeHalfLayout& half(int index) { return shared_->layout.halves[static_cast<std::size_t>(index)]; }
  static Point2 edge_middle(int h, EdgeKind kind) {
    const std::vector<Point2> points = half(h).edge_points(kind);
    return points[points.size() / 2];
  }

  static inline Shared* shared_ = nullptr;
};

// Measured on the generated EU 42 right last: centre lines 4.25 mm rms, 7.74 mm at worst (the toe end of
// the front seam), 331 samples; the medial half turned by 0.70 degrees after its mirroring.
TEST_F(FormeStyle, MedialHalfIsMirroredOntoTheLateralsCentreLine) {
  const FormeLayout& layout = shared_->layout;
  // The fit's own figure, recomputed here from the laid halves at equal shares of each seam.
  double squares = 0, worst = 0;
  int samples = 0;
  for (const EdgeKind seam : {EdgeKind::FrontSeam, EdgeKind::BackSeam}) {
    const int steps = static_cast<int>(half(1).edge_length_mm(seam) / 0.25);  // each millimetre of seam weighs the same
    for (int k = 0; k <= steps; ++k) {
      std::array<Point2, 2> at;
      for (int h = 0; h < 2; ++h) {
        const EdgeSpot spot = spot_at_share(half(h).boundary.edge(seam), static_cast<double>(k) / steps);
        at[static_cast<std::size_t>(h)] = (1 - spot.weight_b) * half(h).forme_uv_mm.row(spot.a).transpose() +
                                          spot.weight_b * half(h).forme_uv_mm.row(spot.b).transpose();
      }
      const double gap = (at[0] - at[1]).norm();
      squares += gap * gap, worst = std::max(worst, gap), ++samples;
    }
  }
  const double rms = std::sqrt(squares / samples);
  std::printf("centre lines: %.3f mm rms, %.3f mm worst (layout: %.3f, %.3f of %d samples), turn %.2f deg\n", rms, worst,
              layout.centre_rms_mm, layout.centre_worst_mm, layout.centre_samples, layout.rotation_deg);
  EXPECT_NEAR(rms, layout.centre_rms_mm, 0.05);
  EXPECT_LT(rms, 4.5);
  EXPECT_LT(worst, 8.0);
  EXPECT_LT(std::abs(layout.rotation_deg), 2.0);
  // Both halves face the same way: heel left of toe, the top edge on the same side of the feather line.
  for (int h = 0; h < 2; ++h) {
    EXPECT_LT(half(h).landmark("heel").x(), half(h).landmark("toe").x()) << h;
    EXPECT_GT(edge_middle(h, EdgeKind::Top).y(), edge_middle(h, EdgeKind::Feather).y()) << h;
  }
  EXPECT_TRUE(half(0).mirrored);
  EXPECT_FALSE(half(1).mirrored);
  // The lateral half is its flattening as it is.
  EXPECT_EQ((half(1).forme_uv_mm - half(1).segment->UV).norm(), 0.0);
}

TEST_F(FormeStyle, DerbyDrawnOnTheFormeLiftsOntoItsLines) {
  const auto [drawn, texts] = derby_drawing();
  ASSERT_EQ(drawn.size(), 4u);  // vamp and counter, each on both halves
  const LiftedForme lifted = lift(read_drawing("derby.dxf", drawn, texts));
  ASSERT_EQ(lifted.lines.size(), 2u);  // each line's halves joined on the centre line
  double worst = 0, worst_to_chords = 0;
  std::size_t points = 0;
  for (const StyleLine& line : lifted.lines) {
    const auto original = std::find_if(shared_->derby.style.lines.begin(), shared_->derby.style.lines.end(),
                                       [&](const StyleLine& candidate) { return candidate.name == line.name; });
    ASSERT_NE(original, shared_->derby.style.lines.end()) << line.name;
    const test::Polyline& on_last = shared_->derby_on_surface[static_cast<std::size_t>(original - shared_->derby.style.lines.begin())];
    for (const Eigen::Vector3d& p : line.points_mm) {
      worst = std::max(worst, test::distance_to_polyline(p, on_last));
      worst_to_chords = std::max(worst_to_chords, test::distance_to_polyline(p, original->points_mm));
    }
    points += line.points_mm.size();
    // Both ends on the feather line, the line across both halves: as the transfer reads it.
    const TransferredCurve curve = shared_->identity->transfer_curve(line.points_mm);
    ASSERT_GE(curve.points.size(), 2u);
    for (const TransferredPoint* end : {&curve.points.front(), &curve.points.back()}) {
      EXPECT_TRUE(end->on_outline && end->edge == EdgeKind::Feather) << line.name;
    }
    EXPECT_NE(curve.points.front().half, curve.points.back().half) << line.name;
    EXPECT_EQ(curve.dropped_points, 0) << line.name;
  }
  std::printf("derby lifted from the forme: %zu points, worst %.4f mm from the 3D lines on the last (%.4f mm from their chords)\n",
              points, worst, worst_to_chords);
  EXPECT_LT(worst, 0.1);
  // A text lands where its label's point is when both lie on the same half (a text not beginning
  // "medial " is lifted on the lateral half).
  ASSERT_EQ(lifted.pieces.size(), shared_->derby.style.pieces.size());
  for (std::size_t p = 0; p < lifted.pieces.size(); ++p) {
    const StylePiece& label = shared_->derby.style.pieces[p];
    EXPECT_EQ(lifted.pieces[p].name, label.name);
    const TransferredPoint at = shared_->identity->transfer_point(label.label_mm).value();
    if ((at.half == "medial") == label.name.starts_with("medial ")) {
      EXPECT_LT((lifted.pieces[p].label_mm - at.position_mm).norm(), 0.1) << label.name;
    }
  }
}

// One polyline on LINE-vamp (both halves): the lateral stretch of the derby's vamp line. Its lateral lift
// is the derby's line; its medial lift joins it on the front seam into one line from feather to feather.
TEST_F(FormeStyle, LineForBothHalvesIsOneLineAcrossTheCentreLine) {
  const auto [drawn, texts] = derby_drawing();
  std::vector<test::DrawnPolyline> lines;
  for (const test::DrawnPolyline& line : drawn)
    if (line.layer == "LINE-lateral-vamp") lines.push_back({"LINE-vamp", line.points_mm});
  ASSERT_EQ(lines.size(), 1u);
  const LiftedForme lifted = lift(read_drawing("plain.dxf", lines, texts));
  ASSERT_EQ(lifted.lines.size(), 1u);
  const TransferredCurve curve = shared_->identity->transfer_curve(lifted.lines[0].points_mm);
  EXPECT_TRUE(curve.points.front().on_outline && curve.points.front().edge == EdgeKind::Feather);
  EXPECT_TRUE(curve.points.back().on_outline && curve.points.back().edge == EdgeKind::Feather);
  int half_changes = 0;
  std::optional<Eigen::Vector3d> join;
  for (std::size_t i = 1; i < curve.points.size(); ++i)
    if (curve.points[i].half != curve.points[i - 1].half) {
      ++half_changes;
      EXPECT_TRUE(curve.points[i].on_outline && curve.points[i].edge == EdgeKind::FrontSeam);
      join = curve.points[i].position_mm;
    }
  EXPECT_EQ(half_changes, 1);
  ASSERT_TRUE(join);
  // The lateral part is the derby's line, but for its end: the halves' centre lines lie apart on the
  // forme, the line reaches them at two points of the seam, and it is joined halfway between them.
  const test::Polyline& on_last = shared_->derby_on_surface[0];
  ASSERT_EQ(shared_->derby.style.lines[0].name, "vamp");
  double worst_lateral = 0, join_shift = INFINITY;
  for (const TransferredPoint& p : curve.points) {
    if (p.half != "lateral") continue;
    const double distance = test::distance_to_polyline(p.position_mm, on_last);
    if ((p.position_mm - *join).norm() > 5.0) worst_lateral = std::max(worst_lateral, distance);
  }
  join_shift = test::distance_to_polyline(*join, on_last);
  std::printf("vamp drawn once for both halves: lateral part %.4f mm from the 3D line at worst (beyond 5 mm of the join); "
              "the join %.2f mm off it\n", worst_lateral, join_shift);
  EXPECT_LT(worst_lateral, 0.1);
  EXPECT_LT(join_shift, 0.5 * kFormeJoinGap_mm);
}

TEST_F(FormeStyle, ALineFarOutsideTheFormeIsRefused) {
  const std::vector<Point2> medial = half(0).outline(), lateral = half(1).outline();
  Point2 low = Point2::Constant(INFINITY);
  for (const Point2& p : lateral) low = low.cwiseMin(p);
  const Point2 outside = low + Point2(120, -20), inside = edge_middle(1, EdgeKind::Feather);
  const std::string file = (shared_->dir / "far.dxf").string();
  const double distance = std::min(distance_to_outline(medial, outside), distance_to_outline(lateral, outside));
  EXPECT_EQ(refusal("far.dxf", {{"LINE-far", {outside, inside}}}, {{"vamp", edge_middle(1, EdgeKind::Top) + Point2(0, -30)}}),
            file + ": line far (layer LINE-far) runs " + one_decimal(distance) + " mm outside the forme at " +
                forme_point_text(outside) + ": a line lies on the forme, at most 2 mm past its outline");
}

TEST_F(FormeStyle, ALineEndingInsideTheUpperIsRefused) {
  const Point2 feather = edge_middle(1, EdgeKind::Feather), top = edge_middle(1, EdgeKind::Top);
  const Point2 middle = 0.5 * (feather + top);
  const std::string file = (shared_->dir / "stub.dxf").string();
  EXPECT_EQ(refusal("stub.dxf", {{"LINE-lateral-stub", {feather, middle}}}, {{"quarter", top + Point2(0, -10)}}),
            file + ": line stub (layer LINE-lateral-stub) ends inside the upper at " + forme_point_text(middle) +
                " on the lateral half: end it on the feather line, the top edge, the centre line or another line (within 1 mm)");
}

TEST_F(FormeStyle, APieceTextOutsideTheFormeIsRefused) {
  const std::vector<Point2> lateral = half(1).outline();
  const Point2 outside = edge_middle(1, EdgeKind::Feather) + Point2(0, -25);
  const std::string file = (shared_->dir / "text.dxf").string();
  EXPECT_EQ(refusal("text.dxf", {}, {{"vamp", outside}}),
            file + ": piece text \"vamp\" at " + forme_point_text(outside) + " lies " + one_decimal(distance_to_outline(lateral, outside)) +
                " mm outside the lateral half: put it inside its piece (a text beginning \"medial \" labels the medial half)");
}

TEST_F(FormeStyle, APieceNamedTwiceIsRefused) {
  const Point2 a = edge_middle(1, EdgeKind::Top) + Point2(0, -10), b = edge_middle(1, EdgeKind::Feather) + Point2(0, 10);
  const std::string file = (shared_->dir / "twice.dxf").string();
  EXPECT_EQ(refusal("twice.dxf", {}, {{"vamp", a}, {"vamp", b}}),
            file + ": piece vamp is named twice on layer PIECES, at " + forme_point_text(a) + " and " + forme_point_text(b) +
                ": one text per piece");
}

}  // namespace
}  // namespace lastcut
