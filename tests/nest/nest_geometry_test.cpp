// The exact collision predicate of the nester on the case that let a piece sit inside another in a
// layout (ESICUP fu, pieces 5 and 9 after a strip shrink): no edges cross, and the inner piece's first
// vertex lies on the outer piece's boundary, where a crossing-number test may answer either way.
// Containment is decided on a point well inside each piece (its largest pole) instead.
#include <gtest/gtest.h>

#include "engine/nest/nest_geometry.hpp"
#include "engine/nest/nest_shapes.hpp"

namespace lastcut::nest_detail {
namespace {

const OrientedShape& pose_of(const PreparedItem& item, double rotation_deg) {
  for (const OrientedShape& s : item.orientations)
    if (s.pose.rotation_deg == rotation_deg) return s;
  throw std::runtime_error("no such pose");
}

PlacedRing placed(const OrientedShape& s, const Point2& offset, bool with_interior) {
  return {&s.outline, s.box, offset, with_interior ? &s.poles.front().center : nullptr};
}

TEST(NestGeometry, PieceInsideAnotherWithAVertexOnItsBoundaryCollides) {
  NestItem square, quad;
  square.shape.points = {{0, 0}, {14, 0}, {14, 14}, {0, 14}};
  square.allowed_rotations_deg = {0, 90, 180, 270};
  quad.shape.points = {{0, 0}, {10, 0}, {10, 10}, {0, 14}};
  quad.allowed_rotations_deg = square.allowed_rotations_deg;
  const PreparedItem a = prepare_item(square, 0, 0.0, 15);
  const PreparedItem b = prepare_item(quad, 1, 0.0, 15);
  const OrientedShape& outer = pose_of(a, 270);
  const OrientedShape& inner = pose_of(b, 90);
  // Where the nester had put them (exact offsets of that layout): the quad inside the square, sharing
  // its right edge. With the quad's first vertex as the containment probe this pair read as apart.
  const Point2 outer_at(2.5717582782094417e-15, 14.000000000000002), inner_at(14, 3.2839692174306521);
  for (const double dy : {0.0, 1.0, 2.5}) {
    const Point2 at = inner_at + Point2(0, dy);
    EXPECT_TRUE(rings_collide(placed(inner, at, true), placed(outer, outer_at, true))) << dy;
    EXPECT_TRUE(rings_collide(placed(outer, outer_at, true), placed(inner, at, true))) << dy;
  }
  // Apart, they do not collide.
  EXPECT_FALSE(rings_collide(placed(inner, inner_at + Point2(20, 0), true), placed(outer, outer_at, true)));
  EXPECT_FALSE(rings_collide(placed(outer, outer_at, true), placed(inner, inner_at + Point2(20, 0), true)));
}

}  // namespace
}  // namespace lastcut::nest_detail
