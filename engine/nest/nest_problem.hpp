#pragma once
// The nesting problem: pieces (items) to cut from a strip of fixed height (rolls, sheets) or from
// leather hides (irregular outline, defects as holes, zones of lower quality).
// Units: millimetres and degrees. Polygons are simple; item shapes are counter-clockwise in the
// item's own frame, which is where its marks and grain direction are given too.
#include <optional>
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

// A pen or notch line drawn on the piece, in the item's own frame (mm).
struct ItemMark {
  std::string name;
  Point2 from_mm = Point2::Zero();
  Point2 to_mm = Point2::Zero();
};

// A part of a piece that needs better leather than the rest of it (the toe and vamp of a shoe mold,
// which show on the finished shoe), in the item's own frame (mm).
struct QualityRegion {
  Polygon2 shape;       // counter-clockwise, inside the item's shape
  int min_quality = 0;  // this region may not overlap a zone whose quality is below this
};

struct NestItem {
  int id = 0;
  Polygon2 shape;                             // counter-clockwise, own frame, mm
  int demand = 1;                             // how many copies to cut
  std::vector<double> allowed_rotations_deg;  // counter-clockwise about the own origin; empty = free rotation
  bool allow_mirror = false;                  // a left/right pair: one item with mirror allowed, or two items
  std::optional<double> grain_deg;            // grain direction in the own frame; must end up along the bin's x axis
  double grain_tolerance_deg = 0;             // allowed deviation from the x axis (either direction)
  int min_quality = 0;                        // may not overlap a zone whose quality is below this
  std::vector<QualityRegion> quality_regions;  // parts of the piece with a stricter min_quality than the whole
  std::string pair_group;                     // items sharing a non-empty group (the left and right molds of one
                                              // order) go on one hide, near each other, or none of them is placed
  // The same piece for the other foot: an item made as another's mirror image (x -> -x in the own
  // frame) shares its non-empty key, so a hide may cut the two mirrored about its backbone.
  std::string mirror_key;
  int priority = 0;                           // when not every piece fits, higher priority is placed first
                                              // (the daemon: older jobs)
  std::string label;                          // short text drawn by the pen (order, size, L/R)
  std::vector<ItemMark> marks;
  // Lines the pen draws on the piece and nothing ever cuts (a pattern's internal lines, its sew
  // lines): polylines of >= 2 points each, in the item's own frame (mm). Mirrored and turned with
  // the piece like its marks; a machine without a pen leaves them out.
  std::vector<std::vector<Point2>> drawn_lines_mm;
};

// A region of a hide with leather of the given quality (lower = worse).
struct QualityZone {
  Polygon2 shape;
  int quality = 0;
};

// A hide or sheet: outer outline, defects (holes: nothing may be cut there), quality zones.
struct Bin {
  int id = 0;
  std::string name;                  // the hide's own id (digitizer or stock number), for reports
  std::optional<double> backbone_deg;  // the hide's grain (backbone) direction, counter-clockwise from its x
                                       // axis; when set, items' grain follows it instead of the x axis
  std::optional<Point2> backbone_point;  // a point of the backbone line, when the hide file drew it (mm);
                                         // else the line runs through the outline's centroid
  Polygon2 outer;
  std::vector<Polygon2> holes;
  std::vector<QualityZone> zones;
  int stock = 1;    // how many identical copies are available
  double cost = 1;  // relative price of one copy
};

// Strip packing when strip_height is set (the strip runs along +x from x = 0, height along y),
// otherwise bin packing on `bins`.
struct NestInstance {
  std::string name;
  std::optional<double> strip_height;  // mm
  std::vector<Bin> bins;
  std::vector<NestItem> items;
  double gap_mm = 0;     // minimum distance between two pieces (kerf + clearance)
  double margin_mm = 0;  // minimum distance between a piece and the strip or hide edge and defects
  // Hides: two pieces of one pair group are near when their centroids are at most this far apart;
  // 0 = the mean of their bounding box diagonals plus the gap (pieces side by side).
  double pair_distance_mm = 0;
};

}  // namespace lastcut
