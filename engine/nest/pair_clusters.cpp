#include "engine/nest/pair_clusters.hpp"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

#include "engine/nest/clipper_paths.hpp"
#include "engine/nest/nest_geometry.hpp"
#include "engine/nest/nest_shapes.hpp"

namespace lastcut {
namespace {

using nest_detail::Box;
using nest_detail::bounding_box;
using nest_detail::normalise_deg;

// A pair must fill this share of its box: only near-perfect complements are worth fixing for the search.
constexpr double kMinFill = 0.95;
// ... and fill it clearly better than the first piece alone.
constexpr double kMinGain = 0.05;

// The ring turned counter-clockwise by deg about the own origin.
std::vector<Point2> rotated(const std::vector<Point2>& ring, double deg) {
  std::vector<Point2> out;
  out.reserve(ring.size());
  for (const Point2& p : ring) out.push_back(nest_detail::apply_pose(p, {deg, false}));
  return out;
}

bool allows(const NestItem& item, double deg) {
  for (double r : item.allowed_rotations_deg)
    if (std::abs(normalise_deg(r) - normalise_deg(deg)) < 1e-6) return true;
  return false;
}

// The vertex-to-vertex search costs #rotations x #P_a x #P_b per pair of items and runs before the
// time limit starts: pieces with many vertices (molds, free curves) are left to the search itself.
constexpr size_t kMaxVertices = 64;

bool eligible(const NestItem& item) {
  return item.demand > 0 && !item.allow_mirror && !item.grain_deg && allows(item, 0) && item.shape.points.size() >= 3 &&
         item.shape.points.size() <= kMaxVertices;
}

// Intersection or union of two closed paths.
ClipperLib::Paths clip(ClipperLib::ClipType type, const ClipperLib::Path& a, const ClipperLib::Path& b) {
  ClipperLib::Clipper clipper;
  clipper.AddPath(a, ClipperLib::ptSubject, true);
  clipper.AddPath(b, ClipperLib::ptClip, true);
  ClipperLib::Paths out;
  clipper.Execute(type, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return out;
}

struct Candidate {
  size_t first = 0, second = 0;  // item indices
  double fill = 0;
  ClusterMember member;          // the second piece in the first one's frame
  Polygon2 shape;                // the union, counter-clockwise
};

// The best way to put `second` against `first`, if one qualifies: candidate offsets put a corner of
// the second piece (in each allowed rotation) on a corner of the first; cheap box arithmetic discards
// almost all of them before Clipper checks overlap and union.
std::optional<Candidate> best_pair(const NestInstance& instance, size_t first, size_t second) {
  const NestItem& a = instance.items[first];
  const NestItem& b = instance.items[second];
  const Box box_a = bounding_box(a.shape.points);
  const double area_a = std::abs(signed_area(a.shape)), area_b = std::abs(signed_area(b.shape));
  const Box own_b = bounding_box(b.shape.points);
  const double alone = std::max(area_a / (box_a.width() * box_a.height()), area_b / (own_b.width() * own_b.height()));
  if (alone + kMinGain > 1) return std::nullopt;
  double extent = 1;
  for (const Point2& p : a.shape.points) extent = std::max({extent, std::abs(p.x()), std::abs(p.y())});
  extent += own_b.width() + own_b.height();
  const double scale = 1e9 / (extent + box_a.width() + box_a.height());  // Clipper units per mm
  const ClipperLib::Path path_a = nest_detail::to_path(a.shape.points, scale);
  const double tolerance = 1e-9 * std::min(area_a, area_b) * scale * scale;
  std::optional<Candidate> best;
  for (double rotation : b.allowed_rotations_deg) {
    const std::vector<Point2> ring = rotated(b.shape.points, rotation);
    const Box box_b = bounding_box(ring);
    for (const Point2& corner_a : a.shape.points)
      for (const Point2& corner_b : ring) {
        const Point2 offset = corner_a - corner_b;
        const Box moved = box_b.shifted(offset);
        const Box both{std::min(box_a.x0, moved.x0), std::min(box_a.y0, moved.y0), std::max(box_a.x1, moved.x1),
                       std::max(box_a.y1, moved.y1)};
        const double fill = (area_a + area_b) / (both.width() * both.height());
        if (fill < std::max(kMinFill, alone + kMinGain) || fill > 1 + 1e-6 || (best && fill <= best->fill)) continue;
        const ClipperLib::Path path_b = nest_detail::to_path(ring, scale, offset);
        double overlap = 0;
        for (const auto& p : clip(ClipperLib::ctIntersection, path_a, path_b)) overlap += std::abs(ClipperLib::Area(p));
        if (overlap > tolerance) continue;
        ClipperLib::Paths merged = clip(ClipperLib::ctUnion, path_a, path_b);
        ClipperLib::CleanPolygons(merged);
        if (merged.size() != 1) continue;  // touching at a point only, or a hole left between them
        Candidate c{first, second, fill, {b.id, normalise_deg(rotation), offset}, {}};
        // Clipper rounds to its integer grid: take the exact corner of either piece each point stands for,
        // so that the pair's outline holds both pieces exactly.
        for (const auto& p : merged.front()) {
          Point2 point(static_cast<double>(p.X) / scale, static_cast<double>(p.Y) / scale);
          double nearest = 4.0 / scale;
          for (const Point2& q : a.shape.points)
            if ((q - point).norm() < nearest) nearest = (q - point).norm(), point = q;
          for (const Point2& q : ring)
            if ((q + offset - point).norm() < nearest) nearest = (q + offset - point).norm(), point = q + offset;
          c.shape.points.push_back(point);
        }
        make_counter_clockwise(c.shape);
        best = std::move(c);
      }
  }
  return best;
}

// The pair fits the strip in at least one of its rotations.
bool fits_strip(const NestInstance& instance, const NestItem& cluster, double margin_mm) {
  if (!instance.strip_height) return true;
  for (double r : cluster.allowed_rotations_deg)
    if (bounding_box(rotated(cluster.shape.points, r)).height() <= *instance.strip_height - 2 * margin_mm) return true;
  return false;
}

}  // namespace

PairClusters cluster_pairs(const NestInstance& instance, double gap_mm, double margin_mm) {
  PairClusters result{instance, {}};
  if (gap_mm > 0) return result;
  std::vector<Candidate> candidates;
  for (size_t i = 0; i < instance.items.size(); ++i) {
    if (!eligible(instance.items[i])) continue;
    for (size_t j = 0; j < instance.items.size(); ++j) {
      if (!eligible(instance.items[j]) || instance.items[i].min_quality != instance.items[j].min_quality) continue;
      if (auto c = best_pair(instance, i, j)) candidates.push_back(std::move(*c));
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) { return x.fill > y.fill; });
  int next_id = 0;
  for (const NestItem& item : instance.items) next_id = std::max(next_id, item.id + 1);
  std::vector<NestItem>& items = result.instance.items;
  for (const Candidate& c : candidates) {
    const int count = c.first == c.second ? items[c.first].demand / 2 : std::min(items[c.first].demand, items[c.second].demand);
    if (count <= 0) continue;
    NestItem cluster;
    cluster.id = next_id;
    cluster.shape = c.shape;
    cluster.demand = count;
    cluster.min_quality = items[c.first].min_quality;
    for (double r : items[c.first].allowed_rotations_deg)
      if (allows(items[c.second], r + c.member.rotation_deg)) cluster.allowed_rotations_deg.push_back(r);
    if (cluster.allowed_rotations_deg.empty() || !fits_strip(instance, cluster, margin_mm)) continue;
    cluster.label = items[c.first].label.empty() ? "" : items[c.first].label + " + " + items[c.second].label;
    items[c.first].demand -= count;
    items[c.second].demand -= count;
    result.members[next_id] = {{items[c.first].id, 0, Point2::Zero()}, c.member};
    items.push_back(std::move(cluster));
    ++next_id;
  }
  return result;
}

Layout expand_clusters(const Layout& clustered, const PairClusters& clusters, const NestInstance& original) {
  Layout layout = clustered;
  layout.placements.clear();
  layout.unplaced.clear();
  for (const Placement& p : clustered.placements) {
    const auto found = clusters.members.find(p.item);
    if (found == clusters.members.end()) {
      layout.placements.push_back(p);
      continue;
    }
    for (const ClusterMember& m : found->second) {
      Placement q = p;
      q.item = m.item_id;
      q.rotation_deg = normalise_deg(p.rotation_deg + m.rotation_deg);
      const Point2 at = place_point(m.offset, p);  // the pair is never mirrored
      q.x = at.x(), q.y = at.y();
      layout.placements.push_back(q);
    }
  }
  for (const Unplaced& u : clustered.unplaced) {
    const auto found = clusters.members.find(u.item);
    if (found == clusters.members.end()) {
      layout.unplaced.push_back(u);
      continue;
    }
    for (const ClusterMember& m : found->second) layout.unplaced.push_back({m.item_id, u.count, u.reason});
  }
  update_utilisation(layout, original);
  return layout;
}

}  // namespace lastcut
