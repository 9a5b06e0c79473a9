#include "engine/style/upper_regions.hpp"

#include <cmath>
#include <numeric>
#include <sstream>

#include "engine/core/engine_error.hpp"
#include "engine/mold/clipper_paths.hpp"
#include "engine/style/forme_boundary.hpp"

namespace lastcut {
namespace {

constexpr double kLineOvershoot_mm = 0.5;   // a line ending on the outline is lengthened this far past it
constexpr double kSeamStep_mm = 0.5;        // seam samples this far apart
constexpr double kSeamInset_mm = 0.05;      // a seam sample is tested this far inside each half
constexpr double kNearCrossing_mm = 2.5;    // seam samples this close to a line are skipped
constexpr double kCrumb_mm2 = 0.5;          // smaller regions are crumbs where strips meet the outline, not pieces

using Run = std::vector<Point2>;  // a line's stretch on one half, in its flattening (mm)

ClipperLib::IntPoint to_int(const Point2& p) { return to_clipper_path({p}).front(); }

// Each line split at the seams into the stretches on each half, lengthened past the outline at ends on it.
std::array<std::vector<Run>, 2> runs_per_half(const std::vector<TransferredCurve>& lines) {
  std::array<std::vector<Run>, 2> runs;
  for (const TransferredCurve& line : lines) {
    std::vector<std::pair<int, Run>> line_runs;  // (half, run) in the line's order
    std::size_t begin = 0;
    while (begin < line.points.size()) {
      std::size_t end = begin + 1;
      while (end < line.points.size() && line.points[end].half == line.points[begin].half) ++end;
      Run run;
      for (std::size_t i = begin; i < end; ++i) run.push_back(line.points[i].forme_uv_mm);
      if (run.size() >= 2) {
        if (line.points[begin].on_outline) run.front() += kLineOvershoot_mm * (run[0] - run[1]).normalized();
        if (line.points[end - 1].on_outline) run.back() += kLineOvershoot_mm * (run[run.size() - 1] - run[run.size() - 2]).normalized();
      }
      line_runs.emplace_back(half_index(line.points[begin].half), std::move(run));
      begin = end;
    }
    // A closed line starts and ends at one point in the middle of a half: its last and first runs are
    // one stretch, joined here so their strips do not meet end to end (where they could leave a point
    // through which the regions on the two sides touch).
    const bool closed = line.points.size() > 2 && line_runs.size() > 1 &&
                        (line.points.front().position_mm - line.points.back().position_mm).norm() < 1e-9 &&
                        line_runs.front().first == line_runs.back().first;
    if (closed) {
      Run& last = line_runs.back().second;
      last.insert(last.end(), line_runs.front().second.begin() + 1, line_runs.front().second.end());
      line_runs.erase(line_runs.begin());
    }
    for (auto& [half, run] : line_runs)
      if (run.size() >= 2) runs[static_cast<std::size_t>(half)].push_back(std::move(run));
  }
  return runs;
}

ClipperLib::Path outline_path(const SegmentResult& half) {
  std::vector<Point2> points;
  for (const int v : half.topology.boundary_loops.front()) points.push_back(half.UV.row(v).transpose());
  ClipperLib::Path path = to_clipper_path(points);
  if (!ClipperLib::Orientation(path)) ClipperLib::ReversePath(path);
  return path;
}

// The half's outline minus the strips of its runs, as regions (outer ring and holes each).
std::vector<HalfRegion> split_half(int half, const ClipperLib::Path& outline, const std::vector<Run>& runs) {
  ClipperLib::ClipperOffset offset(2.0, kStripHalfWidth_mm * kClipperUnitsPerMm / 4);  // round ends and joins of a few points
  for (const Run& run : runs) offset.AddPath(to_clipper_path(run), ClipperLib::jtRound, ClipperLib::etOpenRound);
  ClipperLib::Paths strips;
  offset.Execute(strips, kStripHalfWidth_mm * kClipperUnitsPerMm);
  ClipperLib::Clipper clipper;
  clipper.AddPath(outline, ClipperLib::ptSubject, true);
  clipper.AddPaths(strips, ClipperLib::ptClip, true);
  ClipperLib::PolyTree tree;
  clipper.Execute(ClipperLib::ctDifference, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  std::vector<HalfRegion> regions;
  // Outer rings sit at even depths of the tree, their holes are their children.
  std::vector<const ClipperLib::PolyNode*> pending(tree.Childs.begin(), tree.Childs.end());
  while (!pending.empty()) {
    const ClipperLib::PolyNode* node = pending.back();
    pending.pop_back();
    if (std::abs(ClipperLib::Area(node->Contour)) < kCrumb_mm2 * kClipperUnitsPerMm * kClipperUnitsPerMm) continue;
    HalfRegion region{half, {node->Contour}};
    for (const ClipperLib::PolyNode* hole : node->Childs) {
      region.rings.push_back(hole->Contour);
      pending.insert(pending.end(), hole->Childs.begin(), hole->Childs.end());
    }
    regions.push_back(std::move(region));
  }
  return regions;
}

bool region_holds(const HalfRegion& region, const Point2& point) {
  const ClipperLib::IntPoint p = to_int(point);
  if (ClipperLib::PointInPolygon(p, region.rings.front()) == 0) return false;
  for (std::size_t i = 1; i < region.rings.size(); ++i)
    if (ClipperLib::PointInPolygon(p, region.rings[i]) == 1) return false;
  return true;
}

int region_at(const std::vector<HalfRegion>& regions, std::size_t first, std::size_t count, const Point2& point) {
  for (std::size_t r = first; r < first + count; ++r)
    if (region_holds(regions[r], point)) return static_cast<int>(r);
  return -1;
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) { return parent[static_cast<std::size_t>(i)] == i ? i : parent[static_cast<std::size_t>(i)] = find(parent[static_cast<std::size_t>(i)]); }
  void join(int a, int b) { parent[static_cast<std::size_t>(find(a))] = find(b); }
};

// A point just inside the half next to its outline point p (mm), or p itself when neither side is inside.
Point2 inset(const ClipperLib::Path& outline, const Point2& p, const Point2& along) {
  const Point2 normal = Point2(-along.y(), along.x()).normalized();
  for (const double side : {1.0, -1.0}) {
    const Point2 candidate = p + side * kSeamInset_mm * normal;
    if (ClipperLib::PointInPolygon(to_int(candidate), outline) == 1) return candidate;
  }
  return p;
}

double distance_to_runs(const std::vector<Run>& runs, const Point2& p) {
  double nearest = INFINITY;
  for (const Run& run : runs)
    for (const Point2& q : run) nearest = std::min(nearest, (q - p).norm());
  return nearest;
}

std::string where(const HalfRegion& region) {
  const ClipperLib::IntPoint& p = region.rings.front().front();
  std::ostringstream text;
  text.precision(0);
  text << std::fixed << (region.half == 0 ? "medial" : "lateral") << " forme (" << static_cast<double>(p.X) / kClipperUnitsPerMm
       << ", " << static_cast<double>(p.Y) / kClipperUnitsPerMm << ") mm";
  return text.str();
}

}  // namespace

int half_index(const std::string& half_name) {
  if (half_name == "medial") return 0;
  if (half_name == "lateral") return 1;
  throw EngineError("a style needs medial and lateral halves, not " + half_name);
}

std::vector<PieceRegion> piece_regions(const std::array<const SegmentResult*, 2>& halves,
                                       const std::vector<TransferredCurve>& lines, const std::vector<PieceLabel>& labels,
                                       const std::vector<SeamCut>& seam_cuts, bool labelled_only) {
  const std::array<std::vector<Run>, 2> runs = runs_per_half(lines);
  std::array<ClipperLib::Path, 2> outlines;
  std::vector<HalfRegion> regions;
  std::array<std::size_t, 2> first{}, count{};
  for (int h = 0; h < 2; ++h) {
    outlines[static_cast<std::size_t>(h)] = outline_path(*halves[static_cast<std::size_t>(h)]);
    std::vector<HalfRegion> split = split_half(h, outlines[static_cast<std::size_t>(h)], runs[static_cast<std::size_t>(h)]);
    first[static_cast<std::size_t>(h)] = regions.size();
    count[static_cast<std::size_t>(h)] = split.size();
    regions.insert(regions.end(), split.begin(), split.end());
  }

  // Regions that meet across a seam are one piece.
  UnionFind joined(regions.size());
  std::vector<std::pair<int, PieceRegion::SeamJoin>> joins;  // (a region, the sample that joined it to the other half)
  std::array<FormeBoundary, 2> boundaries = {
      forme_boundary(halves[0]->mesh3d, halves[0]->topology, halves[0]->landmarks),
      forme_boundary(halves[1]->mesh3d, halves[1]->topology, halves[1]->landmarks)};
  for (const EdgeKind seam : {EdgeKind::FrontSeam, EdgeKind::BackSeam}) {
    const FormeEdge& edge0 = boundaries[0].edge(seam);
    double length_mm = 0;
    for (std::size_t i = 1; i < edge0.vertices.size(); ++i)
      length_mm += (halves[0]->mesh3d.V.row(edge0.vertices[i]) - halves[0]->mesh3d.V.row(edge0.vertices[i - 1])).norm();
    const int samples = std::max(2, static_cast<int>(std::ceil(length_mm / kSeamStep_mm)));
    for (int k = 1; k < samples; ++k) {
      const double share = static_cast<double>(k) / samples;
      bool cut = false;
      for (const SeamCut& seam_cut : seam_cuts)
        cut = cut || (seam_cut.seam == seam && share >= seam_cut.from_share && share <= seam_cut.to_share);
      if (cut) continue;
      std::array<int, 2> region{-1, -1};
      for (std::size_t h = 0; h < 2; ++h) {
        const EdgeSpot spot = spot_at_share(boundaries[h].edge(seam), share);
        const Point2 a = halves[h]->UV.row(spot.a).transpose(), b = halves[h]->UV.row(spot.b).transpose();
        const Point2 p = (1 - spot.weight_b) * a + spot.weight_b * b;
        if (distance_to_runs(runs[h], p) < kNearCrossing_mm) break;
        region[h] = region_at(regions, first[h], count[h], inset(outlines[h], p, b - a));
      }
      if (region[0] >= 0 && region[1] >= 0) {
        joined.join(region[0], region[1]);
        joins.push_back({region[0], {seam, share}});
      }
    }
  }

  // Each group of joined regions is the piece whose label lies in it.
  std::vector<int> piece_of_group(regions.size(), -1);
  for (std::size_t p = 0; p < labels.size(); ++p) {
    const int h = half_index(labels[p].point.half);
    const int r = region_at(regions, first[static_cast<std::size_t>(h)], count[static_cast<std::size_t>(h)], labels[p].point.forme_uv_mm);
    if (r < 0) throw EngineError("the label of piece " + labels[p].name + " lies on a style line or off the upper");
    int& owner = piece_of_group[static_cast<std::size_t>(joined.find(r))];
    if (owner >= 0)
      throw EngineError("pieces " + labels[static_cast<std::size_t>(owner)].name + " and " + labels[p].name +
                        " lie in one region: a style line between them is missing or does not reach an edge");
    owner = static_cast<int>(p);
  }
  std::vector<PieceRegion> pieces(labels.size());
  for (std::size_t p = 0; p < labels.size(); ++p) pieces[p].name = labels[p].name;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const int owner = piece_of_group[static_cast<std::size_t>(joined.find(static_cast<int>(r)))];
    if (owner < 0 && labelled_only) continue;
    if (owner < 0) throw EngineError("the region at the " + where(regions[r]) + " has no piece: a label is missing or a line does not reach an edge");
    pieces[static_cast<std::size_t>(owner)].parts.push_back(regions[r]);
  }
  for (const auto& [region, join] : joins) {
    const int owner = piece_of_group[static_cast<std::size_t>(joined.find(region))];
    if (owner >= 0) pieces[static_cast<std::size_t>(owner)].joins.push_back(join);
  }
  return pieces;
}

}  // namespace lastcut
