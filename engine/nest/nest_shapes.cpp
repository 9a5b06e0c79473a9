#include "engine/nest/nest_shapes.hpp"

#include "engine/nest/clipper_paths.hpp"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace lastcut::nest_detail {
namespace {

constexpr int kMaxOutlinePoints = 64;
constexpr int kMaxPoles = 12;

// Wraps an axis angle (a grain line has no direction) into (-90, 90].
double axis_deviation_deg(double angle_deg) {
  double a = std::fmod(angle_deg, 180.0);
  if (a > 90.0) a -= 180.0;
  if (a <= -90.0) a += 180.0;
  return a;
}

bool grain_ok(const NestItem& item, const Pose& pose) {
  if (!item.grain_deg) return true;
  const double own = pose.mirrored ? 180.0 - *item.grain_deg : *item.grain_deg;
  return std::abs(axis_deviation_deg(own + pose.rotation_deg)) <= item.grain_tolerance_deg + 1e-9;
}

std::string format_deg(double deg) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", deg);
  return text;
}

double distance_to_ring(const Point2& p, const std::vector<Point2>& ring) {
  double best = std::numeric_limits<double>::max();
  for (size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point2& a = ring[i];
    const Point2 ab = ring[(i + 1) % n] - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * ab - p).squaredNorm());
  }
  return std::sqrt(best);
}

using ClipperLib::Path;
using ClipperLib::Paths;

// Largest-area ring of an offset result.
Path largest(const Paths& paths) {
  Path best;
  double best_area = 0;
  for (const Path& p : paths)
    if (std::abs(ClipperLib::Area(p)) > best_area) best_area = std::abs(ClipperLib::Area(p)), best = p;
  return best;
}

}  // namespace

double normalise_deg(double a) {
  a = std::fmod(a, 360.0);
  if (a < 0) a += 360.0;
  if (a >= 360.0 - 1e-9) a = 0;
  return a;
}

Point2 apply_pose(const Point2& point, const Pose& pose) {
  const double angle = pose.rotation_deg * std::numbers::pi / 180.0;
  const double c = std::cos(angle), s = std::sin(angle);
  const double x = pose.mirrored ? -point.x() : point.x();
  return {c * x - s * point.y(), s * x + c * point.y()};
}

std::vector<Pose> allowed_poses(const NestItem& item, double free_step_deg) {
  std::vector<double> rotations;
  if (!item.allowed_rotations_deg.empty()) {
    rotations = item.allowed_rotations_deg;
  } else if (item.grain_deg) {
    // Free rotation with grain: sample the tolerance window around both grain-aligned angles.
    for (int mirrored = 0; mirrored < (item.allow_mirror ? 2 : 1); ++mirrored) {
      const double own = mirrored ? 180.0 - *item.grain_deg : *item.grain_deg;
      for (double base : {-own, 180.0 - own})
        for (int k = -2; k <= 2; ++k) rotations.push_back(base + k * item.grain_tolerance_deg / 2.0);
    }
  } else {
    for (double a = 0; a < 360.0 - 1e-9; a += free_step_deg) rotations.push_back(a);
  }
  std::vector<Pose> poses;
  for (int mirrored = 0; mirrored < (item.allow_mirror ? 2 : 1); ++mirrored)
    for (double r : rotations) {
      const Pose pose{normalise_deg(r), mirrored == 1};
      if (!grain_ok(item, pose)) continue;
      bool duplicate = false;
      for (const Pose& q : poses) duplicate |= q.mirrored == pose.mirrored && std::abs(q.rotation_deg - pose.rotation_deg) < 1e-9;
      if (!duplicate) poses.push_back(pose);
    }
  return poses;
}

std::vector<Point2> conservative_outline(const Polygon2& shape, double grow_mm, int max_points) {
  const Box box = bounding_box(shape.points);
  const double diameter = std::hypot(box.width(), box.height());
  if (grow_mm <= 0 && static_cast<int>(shape.points.size()) <= max_points) return shape.points;
  double extent = 0;
  for (const Point2& p : shape.points) extent = std::max({extent, std::abs(p.x()), std::abs(p.y())});
  const double scale = 1e9 / (extent + diameter + grow_mm);
  double tolerance = static_cast<int>(shape.points.size()) <= max_points ? 0.0 : 1e-3 * diameter;
  for (int attempt = 0; attempt < 12; ++attempt, tolerance *= 2) {
    ClipperLib::ClipperOffset offset(2.0, std::max(1.0, 0.25 * tolerance * scale));
    offset.AddPath(to_path(shape.points, scale), ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    Paths grown;
    offset.Execute(grown, (grow_mm + tolerance) * scale);
    std::vector<Point2> outline = simplify_ring(from_path(largest(grown), scale), tolerance);
    if (static_cast<int>(outline.size()) > max_points && attempt < 11) continue;
    // Verify: the shape grown by grow_mm must lie inside the outline.
    Paths required;
    ClipperLib::ClipperOffset exact(2.0, std::max(1.0, 0.25 * tolerance * scale));
    exact.AddPath(to_path(shape.points, scale), ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    exact.Execute(required, grow_mm * scale);
    ClipperLib::Clipper clipper;
    clipper.AddPaths(required, ClipperLib::ptSubject, true);
    clipper.AddPath(to_path(outline, scale), ClipperLib::ptClip, true);
    Paths outside;
    clipper.Execute(ClipperLib::ctDifference, outside, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    double outside_area = 0;
    for (const Path& p : outside) outside_area += std::abs(ClipperLib::Area(p));
    if (outside_area <= 1e-12 * scale * scale * diameter * diameter) {
      Polygon2 ccw{outline};
      make_counter_clockwise(ccw);
      return ccw.points;
    }
  }
  // Simplification never verified: fall back to the grown outline with all its points.
  ClipperLib::ClipperOffset offset(2.0, 1.0);
  offset.AddPath(to_path(shape.points, scale), ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  Paths grown;
  offset.Execute(grown, grow_mm * scale + 1);
  Polygon2 ccw{from_path(largest(grown), scale)};
  make_counter_clockwise(ccw);
  return ccw.points;
}

std::vector<Pole> compute_poles(const std::vector<Point2>& ring, int max_poles) {
  const Box box = bounding_box(ring);
  const int samples = 48;
  const double step = std::max(box.width(), box.height()) / samples;
  struct Sample {
    Point2 p;
    double boundary_distance;
  };
  std::vector<Sample> inside;
  for (double y = box.y0 + step / 2; y < box.y1; y += step)
    for (double x = box.x0 + step / 2; x < box.x1; x += step) {
      const Point2 p(x, y);
      if (point_in_ring(p, ring)) inside.push_back({p, distance_to_ring(p, ring)});
    }
  std::vector<Pole> poles;
  if (inside.empty()) {  // a sliver thinner than the sampling step
    Point2 mean = Point2::Zero();
    for (const Point2& p : ring) mean += p;
    mean /= static_cast<double>(ring.size());
    poles.push_back({mean, step / 4});
    return poles;
  }
  while (static_cast<int>(poles.size()) < max_poles) {
    double best = 0;
    const Sample* chosen = nullptr;
    for (const Sample& s : inside) {
      double r = s.boundary_distance;
      for (const Pole& q : poles) r = std::min(r, (s.p - q.center).norm() - q.radius_mm);
      if (r > best) best = r, chosen = &s;
    }
    if (!chosen || (!poles.empty() && best < 0.1 * poles.front().radius_mm)) break;
    poles.push_back({chosen->p, best});
  }
  return poles;
}

PoleLanes pole_lanes(const std::vector<Pole>& poles) {
  PoleLanes lanes;
  const size_t padded = (poles.size() + 3) / 4 * 4;
  for (size_t k = 0; k < padded; ++k) {
    // A padding pole: radius 0 adds nothing (its weight is the smaller radius), 1e15 mm away keeps its
    // penetration depth finite and negative.
    const bool real = k < poles.size();
    lanes.x.push_back(real ? static_cast<float>(poles[k].center.x()) : 1e15f);
    lanes.y.push_back(real ? static_cast<float>(poles[k].center.y()) : 1e15f);
    lanes.radius.push_back(real ? static_cast<float>(poles[k].radius_mm) : 0.0f);
  }
  return lanes;
}

PreparedItem prepare_item(const NestItem& item, int item_index, double grow_mm, double free_step_deg,
                          const PreparedItem* same_shape) {
  PreparedItem prepared;
  prepared.item_index = item_index;
  prepared.area_mm2 = std::abs(signed_area(item.shape));
  prepared.min_quality = item.min_quality;
  prepared.own_outline = same_shape ? same_shape->own_outline : conservative_outline(item.shape, grow_mm, kMaxOutlinePoints);
  prepared.own_poles = same_shape ? same_shape->own_poles : compute_poles(prepared.own_outline, kMaxPoles);
  const std::vector<Point2>& outline = prepared.own_outline;
  const std::vector<Pole>& poles = prepared.own_poles;
  const Box box = bounding_box(outline);
  prepared.diameter_mm = std::hypot(box.width(), box.height());
  struct Region {
    std::vector<Point2> outline;
    std::vector<Pole> poles;
    int min_quality;
  };
  std::vector<Region> regions;
  for (const QualityRegion& region : item.quality_regions) {
    if (region.min_quality <= item.min_quality || region.shape.points.size() < 3) continue;
    Polygon2 ccw = region.shape;
    make_counter_clockwise(ccw);
    std::vector<Point2> region_outline = conservative_outline(ccw, 0.0, kMaxOutlinePoints);
    std::vector<Pole> region_poles = compute_poles(region_outline, kMaxPoles);
    regions.push_back({std::move(region_outline), std::move(region_poles), region.min_quality});
  }
  for (const Pose& pose : allowed_poses(item, free_step_deg)) {
    OrientedShape oriented;
    oriented.pose = pose;
    for (const Point2& p : outline) oriented.outline.push_back(apply_pose(p, pose));
    Polygon2 ccw{oriented.outline};
    make_counter_clockwise(ccw);
    oriented.outline = std::move(ccw.points);
    oriented.box = bounding_box(oriented.outline);
    for (const Pole& pole : poles) oriented.poles.push_back({apply_pose(pole.center, pose), pole.radius_mm});
    oriented.pole_lanes = pole_lanes(oriented.poles);
    for (const Region& region : regions) {
      OrientedRegion r;
      r.min_quality = region.min_quality;
      for (const Point2& p : region.outline) r.outline.push_back(apply_pose(p, pose));
      Polygon2 ring{r.outline};
      make_counter_clockwise(ring);
      r.outline = std::move(ring.points);
      r.box = bounding_box(r.outline);
      for (const Pole& pole : region.poles) r.poles.push_back({apply_pose(pole.center, pose), pole.radius_mm});
      oriented.regions.push_back(std::move(r));
    }
    prepared.orientations.push_back(std::move(oriented));
  }
  if (prepared.orientations.empty())
    prepared.no_pose_reason = "no allowed rotation puts its grain within " + format_deg(item.grain_tolerance_deg) +
                              " deg of the material's grain (x axis)";
  return prepared;
}

}  // namespace lastcut::nest_detail
