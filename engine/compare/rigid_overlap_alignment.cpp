#include "engine/compare/rigid_overlap_alignment.hpp"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/core/polygon_centroid.hpp"

namespace lastcut {

namespace {

constexpr double kClipperUnitsPerMm = 1e5;  // 1 unit = 1e-5 mm
constexpr double kFirstStep_mm = 4.0;
// Starts are refined together to this step on thinned outlines; only those near the best go on,
// with the full outlines, to the final step.
constexpr double kCoarseStep_mm = 0.05;
constexpr size_t kCoarsePoints = 200;

// Every k-th point, at most about kCoarsePoints: areas within a fraction of a percent, enough
// to tell the starts apart and reach the basin of the best one.
std::vector<Point2> thinned(const std::vector<Point2>& points) {
  const size_t every = std::max<size_t>(1, points.size() / kCoarsePoints);
  std::vector<Point2> kept;
  for (size_t i = 0; i < points.size(); i += every) kept.push_back(points[i]);
  return kept;
}

ClipperLib::Path to_clipper(const std::vector<Point2>& points) {
  ClipperLib::Path path;
  path.reserve(points.size());
  for (const Point2& p : points)
    path.emplace_back(static_cast<ClipperLib::cInt>(std::llround(p.x() * kClipperUnitsPerMm)),
                      static_cast<ClipperLib::cInt>(std::llround(p.y() * kClipperUnitsPerMm)));
  return path;
}

double intersection_area(const ClipperLib::Path& a, const ClipperLib::Path& b) {
  ClipperLib::Clipper clipper;
  clipper.AddPath(a, ClipperLib::ptSubject, true);
  clipper.AddPath(b, ClipperLib::ptClip, true);
  ClipperLib::Paths solution;
  clipper.Execute(ClipperLib::ctIntersection, solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  double area = 0.0;  // outer rings count positive, holes negative
  for (const auto& ring : solution) area += ClipperLib::Area(ring);
  return std::abs(area) / (kClipperUnitsPerMm * kClipperUnitsPerMm);
}

double radius_of_gyration(const Polygon2& polygon, const Point2& centroid) {
  double sum = 0.0;
  for (const auto& p : polygon.points) sum += (p - centroid).squaredNorm();
  return std::max(std::sqrt(sum / static_cast<double>(polygon.points.size())), 1.0);
}

// The search state: angle about the reference's centroid, translation of it from the mold's centroid.
struct SearchPoint {
  bool mirrored = false;
  double angle_rad = 0.0;
  Point2 shift_mm = Point2::Zero();
  double area_mm2 = -1.0;
  double step_mm = kFirstStep_mm;
};

class OverlapSearch {
 public:
  OverlapSearch(const Polygon2& reference, const Polygon2& mold)
      : reference_(reference),
        reference_centroid_(area_centroid(reference)),
        mold_centroid_(area_centroid(mold)),
        mold_path_(to_clipper(mold.points)),
        coarse_reference_(thinned(reference.points)),
        coarse_mold_path_(to_clipper(thinned(mold.points))),
        radius_mm_(radius_of_gyration(reference, reference_centroid_)) {}

  double radius_mm() const { return radius_mm_; }
  int evaluations() const { return evaluations_; }

  PlaneMotion motion_of(const SearchPoint& s) const {
    PlaneMotion motion{s.mirrored, s.angle_rad, Point2::Zero()};
    const Point2 c = motion.apply(reference_centroid_);  // rotation and mirror only so far
    motion.translation_mm = mold_centroid_ + s.shift_mm - c;
    return motion;
  }

  // Intersection area at s, of the full or the thinned outlines.
  double area(const SearchPoint& s, bool coarse) {
    ++evaluations_;
    const PlaneMotion motion = motion_of(s);
    const std::vector<Point2>& reference = coarse ? coarse_reference_ : reference_.points;
    std::vector<Point2> points;
    points.reserve(reference.size());
    for (const auto& p : reference) points.push_back(motion.apply(p));
    return intersection_area(to_clipper(points), coarse ? coarse_mold_path_ : mold_path_);
  }

  // Compass search from s until its step is below final_step.
  void refine(SearchPoint& s, double final_step_mm, bool coarse) {
    if (s.area_mm2 < 0.0) s.area_mm2 = area(s, coarse);
    static const std::array<std::array<double, 3>, 10> directions = [] {
      const double d = std::numbers::sqrt2 / 2.0;
      return std::array<std::array<double, 3>, 10>{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1},
                                                    {0, 0, -1}, {0, d, d}, {0, -d, -d}, {0, d, -d}, {0, -d, d}}};
    }();
    while (s.step_mm >= final_step_mm) {
      SearchPoint best = s;
      for (const auto& dir : directions) {
        SearchPoint trial = s;
        trial.angle_rad += dir[0] * s.step_mm / radius_mm_;
        trial.shift_mm += s.step_mm * Point2(dir[1], dir[2]);
        trial.area_mm2 = area(trial, coarse);
        if (trial.area_mm2 > best.area_mm2) best = trial;
      }
      if (best.area_mm2 > s.area_mm2) s = best;
      else s.step_mm *= 0.5;
    }
  }

 private:
  const Polygon2& reference_;
  Point2 reference_centroid_, mold_centroid_;
  ClipperLib::Path mold_path_;
  std::vector<Point2> coarse_reference_;
  ClipperLib::Path coarse_mold_path_;
  double radius_mm_;
  int evaluations_ = 0;
};

}  // namespace

Point2 PlaneMotion::apply(const Point2& p) const {
  const Point2 q(mirrored ? -p.x() : p.x(), p.y());
  const double c = std::cos(rotation_rad), s = std::sin(rotation_rad);
  return Point2(c * q.x() - s * q.y(), s * q.x() + c * q.y()) + translation_mm;
}

Polygon2 moved(const Polygon2& polygon, const PlaneMotion& motion) {
  Polygon2 result;
  result.points.reserve(polygon.points.size());
  for (const auto& p : polygon.points) result.points.push_back(motion.apply(p));
  if (motion.mirrored) std::reverse(result.points.begin(), result.points.end());
  return result;
}

double intersection_area_mm2(const Polygon2& a, const Polygon2& b) {
  return intersection_area(to_clipper(a.points), to_clipper(b.points));
}

OverlapAlignment align_for_overlap(const Polygon2& reference, const Polygon2& mold, const OverlapOptions& options) {
  OverlapAlignment result;
  result.reference_area_mm2 = std::abs(signed_area(reference));
  result.mold_area_mm2 = std::abs(signed_area(mold));
  if (reference.points.size() < 3 || !(result.reference_area_mm2 > 0.0))
    throw EngineError("the reference pattern has no area");
  if (mold.points.size() < 3 || !(result.mold_area_mm2 > 0.0)) throw EngineError("the mold has no area");
  for (const auto* outline : {&reference, &mold})
    for (const auto& p : outline->points)
      if (!(std::abs(p.x()) <= 1e6 && std::abs(p.y()) <= 1e6))
        throw EngineError("an outline has coordinates beyond 1 km; check its units");

  OverlapSearch search(reference, mold);
  const Point2 mold_axis = principal_axis(mold);
  std::vector<SearchPoint> starts;
  for (bool mirrored : {false, true}) {
    if (mirrored && !options.allow_mirror) continue;
    // The reference's axis after the mirror, before any rotation.
    const PlaneMotion mirror{mirrored, 0.0, Point2::Zero()};
    const Point2 axis = mirror.apply(principal_axis(reference));
    const double base = std::atan2(mold_axis.y(), mold_axis.x()) - std::atan2(axis.y(), axis.x());
    for (int quarter = 0; quarter < 4; ++quarter) {
      SearchPoint start;
      start.mirrored = mirrored;
      start.angle_rad = base + quarter * std::numbers::pi / 2.0;
      starts.push_back(start);
    }
  }
  for (auto& start : starts) search.refine(start, kCoarseStep_mm, true);
  const double best_coarse = std::max_element(starts.begin(), starts.end(), [](const auto& a, const auto& b) {
                               return a.area_mm2 < b.area_mm2;
                             })->area_mm2;
  const double final_step_mm = std::min(options.final_step_mm, options.final_step_rad * search.radius_mm());
  SearchPoint best;
  for (auto& start : starts) {
    // Within 1 % of the best coarse area: close enough that the last 0.05 mm could reorder them.
    if (start.area_mm2 < 0.99 * best_coarse) continue;
    start.area_mm2 = -1.0;  // the coarse area was of the thinned outlines
    start.step_mm = 0.5;    // thinning moves the optimum by a fraction of a millimetre
    search.refine(start, final_step_mm, false);
    if (start.area_mm2 > best.area_mm2) best = start;
  }
  result.motion = search.motion_of(best);
  result.motion.rotation_rad = std::remainder(result.motion.rotation_rad, 2.0 * std::numbers::pi);
  result.intersection_area_mm2 = best.area_mm2;
  result.area_evaluations = search.evaluations();
  return result;
}

}  // namespace lastcut
