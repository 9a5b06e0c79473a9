#include "engine/compare/reference_outline.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

#include "engine/core/engine_error.hpp"
#include "engine/mold/outline_geometry.hpp"

namespace lastcut {

Polygon2 largest_closed_outline(const std::filesystem::path& path, std::vector<Polygon2> rings, int open_count) {
  Polygon2* best = nullptr;
  double best_area = 0.0;
  for (auto& ring : rings) {
    if (ring.points.size() < 3) continue;
    const double area = std::abs(signed_area(ring));
    if (area > best_area) best_area = area, best = &ring;
  }
  if (best == nullptr) {
    std::string reason = path.string() + ": no closed outline";
    if (open_count > 0) reason += " (" + std::to_string(open_count) + " open, close the outline in the drawing program)";
    throw EngineError(reason);
  }
  Polygon2 outline = std::move(*best);
  // Clipper's integers of 1e-5 mm reach far beyond this; a pattern this large has wrong units.
  constexpr double kLargestCoordinate_mm = 1e6;
  for (const auto& p : outline.points)
    if (!(std::abs(p.x()) <= kLargestCoordinate_mm && std::abs(p.y()) <= kLargestCoordinate_mm))
      throw EngineError(path.string() + ": coordinates beyond 1 km; check the drawing's units");
  make_counter_clockwise(outline);
  return outline;
}

namespace {

// Where edges i and j of `outline` (from point i to point i+1) meet: their crossing, or for edges that
// overlap along a line, the start of edge j.
Point2 edges_meet_at(const Polygon2& outline, int i, int j) {
  const size_t n = outline.points.size();
  const Point2 p = outline.points[static_cast<size_t>(i)], r = outline.points[(static_cast<size_t>(i) + 1) % n] - p;
  const Point2 q = outline.points[static_cast<size_t>(j)], s = outline.points[(static_cast<size_t>(j) + 1) % n] - q;
  const double denominator = r.x() * s.y() - r.y() * s.x();
  if (std::abs(denominator) <= 1e-12 * r.norm() * s.norm()) return q;
  const Point2 qp = q - p;
  return p + std::clamp((qp.x() * s.y() - qp.y() * s.x()) / denominator, 0.0, 1.0) * r;
}

}  // namespace

void check_pattern_outline(const std::string& source, const Polygon2& outline) {
  constexpr double kSmallest_mm = 5.0, kLargest_mm = 2000.0, kLongest_mm = 10000.0;
  constexpr size_t kMostPoints = 20000;
  if (outline.points.size() > kMostPoints)
    throw EngineError(source + ": an outline of " + std::to_string(outline.points.size()) +
                      " points, more than 20000; simplify it in the drawing program");
  if (outline.points.size() < 3) throw EngineError(source + ": no closed outline");
  Point2 low = outline.points.front(), high = low;
  for (const Point2& p : outline.points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  const Point2 size = high - low;
  char line[200];
  if (size.maxCoeff() > kLargest_mm || size.maxCoeff() < kSmallest_mm) {
    std::snprintf(line, sizeof line, ": the outline is %.6g x %.6g mm, %s than a shoe pattern; check the drawing's units",
                  size.x(), size.y(), size.maxCoeff() > kLargest_mm ? "larger" : "smaller");
    throw EngineError(source + line);
  }
  if (const double around = perimeter(outline); around > kLongest_mm) {
    std::snprintf(line, sizeof line, ": the outline is %.3g m long, longer than 10 m; it is no shoe pattern", around / 1000.0);
    throw EngineError(source + line);
  }
  // A crossing outline has no one area: the overlap 2C/(A+B) came out above 100 % on one (fuzzing).
  // A point repeated by the drawing program is no crossing, so repeats are dropped for the test.
  Polygon2 distinct;
  for (const Point2& p : outline.points)
    if (distinct.points.empty() || p != distinct.points.back()) distinct.points.push_back(p);
  while (distinct.points.size() > 1 && distinct.points.back() == distinct.points.front()) distinct.points.pop_back();
  if (distinct.points.size() < 3) throw EngineError(source + ": no closed outline");
  if (const auto crossing = find_self_intersection(distinct)) {
    const Point2 at = edges_meet_at(distinct, crossing->first, crossing->second);
    std::snprintf(line, sizeof line,
                  ": the outline crosses or touches itself near (%.1f, %.1f) mm; a pattern is one line that does not "
                  "cross itself, fix it in the drawing program",
                  at.x(), at.y());
    throw EngineError(source + line);
  }
}

Mold read_reference_outline(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (!std::filesystem::is_regular_file(path)) throw EngineError("cannot read pattern file " + path.string());
  if (std::filesystem::file_size(path) == 0) throw EngineError(path.string() + ": the file is empty");
  Mold mold;
  if (extension == ".dxf") {
    mold = read_dxf_outline(path);
  } else if (extension == ".svg") {
    mold.name = path.stem().string();
    mold.outline = read_svg_outline(path);
  } else {
    throw EngineError(path.string() + ": not a pattern file; expected a .dxf or .svg outline");
  }
  check_pattern_outline(path.string(), mold.outline);
  return mold;
}

}  // namespace lastcut
