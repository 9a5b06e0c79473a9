#pragma once
// Layout: where every copy of every item went (or why it did not), the result of nesting.
// A placed shape is the item polygon mirrored (x -> -x) when `mirrored`, rotated counter-clockwise
// by rotation_deg about the item's own origin, then translated by (x, y).
#include <optional>
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

struct Placement {
  int item = 0;  // NestItem::id
  int bin = -1;  // Bin::id on hides; -1 on a strip
  int copy = 0;  // which copy of a bin with stock > 1 (0 for the first)
  double rotation_deg = 0;
  bool mirrored = false;
  double x = 0, y = 0;  // mm
};

// Copies of an item that could not be placed, with the reason an operator reads.
struct Unplaced {
  int item = 0;
  int count = 0;
  std::string reason;
};

struct Layout {
  std::string instance;
  std::optional<double> strip_length;  // mm, strip packing only
  double utilisation = 0;              // placed item area / used material area, 0..1
  std::vector<Placement> placements;
  std::vector<Unplaced> unplaced;
};

// The rigid motion of a placement applied to one point of the item's own frame.
Point2 place_point(const Point2& own, const Placement& placement);
// The item's polygon where the placement puts it (counter-clockwise also when mirrored).
Polygon2 placed_shape(const NestItem& item, const Placement& placement);
// The grain direction (deg) of a placed item, or nullopt when the item has none.
std::optional<double> placed_grain_deg(const NestItem& item, const Placement& placement);

// Item by id; throws EngineError when the id is unknown.
const NestItem& find_item(const NestInstance& instance, int item_id);
// What an operator reads about pieces left over: "m-38-left lateral (item 0) x1: <reason>", or
// "item 0 x1: <reason>" when the item has no label.
std::string unplaced_text(const Unplaced& unplaced, const NestInstance& instance);
// Bin by id; throws EngineError when the id is unknown.
const Bin& find_bin(const NestInstance& instance, int bin_id);

// Area of the material used (mm^2): strip_height x strip_length on a strip; the area of every
// hide that holds at least one piece (outer minus holes) on hides.
double used_material_area(const Layout& layout, const NestInstance& instance);
// Sum of the placed item areas (mm^2).
double placed_item_area(const Layout& layout, const NestInstance& instance);
// Number of hides/sheets used (each copy of a bin with stock > 1 counts).
int used_bin_count(const Layout& layout);
// Sets layout.utilisation from the two areas above (0 when nothing is used).
void update_utilisation(Layout& layout, const NestInstance& instance);

}  // namespace lastcut
