#pragma once
// Exact predicates on small polygons for the nester's collision detection: bounding boxes and
// polygon overlap, on the segment and point-in-ring predicates of engine/core/segment_predicates.hpp.
// Touching counts as colliding, so every layout the nester accepts keeps its pieces strictly apart
// (conservative by design).
#include <vector>

#include "engine/core/polygon.hpp"
#include "engine/core/segment_predicates.hpp"

namespace lastcut::nest_detail {

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // mm
  bool overlaps(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
  bool contains(const Box& o) const { return x0 <= o.x0 && o.x1 <= x1 && y0 <= o.y0 && o.y1 <= y1; }
  Box shifted(const Point2& t) const { return {x0 + t.x(), y0 + t.y(), x1 + t.x(), y1 + t.y()}; }
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  Point2 centre() const { return {0.5 * (x0 + x1), 0.5 * (y0 + y1)}; }
};

// Bounding box of points #P (mm); points must not be empty.
Box bounding_box(const std::vector<Point2>& points);
// A polygon placed by translation: ring in its own (already rotated) frame plus offset.
struct PlacedRing {
  const std::vector<Point2>* ring = nullptr;  // #P points, counter-clockwise
  Box box;                                    // of the ring in its own frame
  Point2 offset = Point2::Zero();             // translation, mm
  // A point well inside the ring (own frame), e.g. its largest pole's centre; null: the first vertex.
  // Decides containment when no edges touch: a vertex can sit on the other ring's boundary, where the
  // crossing test may answer either way, an interior point cannot.
  const Point2* interior = nullptr;
  Box world_box() const { return box.shifted(offset); }
  Point2 interior_point() const { return interior ? *interior : (*ring)[0]; }
};

// Interiors or boundaries of the two placed polygons share a point.
bool rings_collide(const PlacedRing& a, const PlacedRing& b);

// Douglas-Peucker simplification of a closed ring keeping the two farthest-apart points
// (Douglas & Peucker 1973); removed points lie within tolerance_mm of the result.
std::vector<Point2> simplify_ring(const std::vector<Point2>& ring, double tolerance_mm);

}  // namespace lastcut::nest_detail
