#include "engine/nest/clipper_paths.hpp"

#include <cmath>

namespace lastcut::nest_detail {

ClipperLib::Path to_path(const std::vector<Point2>& ring, double scale, const Point2& shift_mm) {
  ClipperLib::Path path;
  path.reserve(ring.size());
  for (const Point2& p : ring)
    path.emplace_back(static_cast<ClipperLib::cInt>(std::llround((p.x() + shift_mm.x()) * scale)),
                      static_cast<ClipperLib::cInt>(std::llround((p.y() + shift_mm.y()) * scale)));
  return path;
}

std::vector<Point2> from_path(const ClipperLib::Path& path, double scale) {
  std::vector<Point2> ring;
  ring.reserve(path.size());
  for (const ClipperLib::IntPoint& p : path) ring.emplace_back(static_cast<double>(p.X) / scale, static_cast<double>(p.Y) / scale);
  return ring;
}

}  // namespace lastcut::nest_detail
