#include "baldacci_hides.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_file.hpp"
#include "engine/nest/nest_json.hpp"

namespace lastcut::bench {

double principal_axis_deg(const Polygon2& outline) {
  // Green's theorem over the edges (shoelace-style sums): area, first and second moments about the
  // origin, then moved to the centroid.
  double area2 = 0, mx = 0, my = 0, ixx = 0, iyy = 0, ixy = 0;
  const std::size_t n = outline.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = outline.points[i];
    const Point2& b = outline.points[(i + 1) % n];
    const double cross = a.x() * b.y() - b.x() * a.y();
    area2 += cross;
    mx += (a.x() + b.x()) * cross;
    my += (a.y() + b.y()) * cross;
    ixx += (a.x() * a.x() + a.x() * b.x() + b.x() * b.x()) * cross;  // integral of x^2, x 12
    iyy += (a.y() * a.y() + a.y() * b.y() + b.y() * b.y()) * cross;  // integral of y^2, x 12
    ixy += (a.x() * b.y() + 2 * a.x() * a.y() + 2 * b.x() * b.y() + b.x() * a.y()) * cross;  // x 24
  }
  const double area = area2 / 2;
  if (!(std::abs(area) > 0)) throw EngineError("a hide outline without area has no principal axis");
  const double cx = mx / (6 * area), cy = my / (6 * area);
  // The signed sums carry the orientation: a clockwise ring gives every moment negated, which would
  // turn the axis by 90 deg, so they are taken with the area's sign.
  const double sign = area > 0 ? 1 : -1;
  const double sxx = sign * (ixx / 12 - area * cx * cx), syy = sign * (iyy / 12 - area * cy * cy),
               sxy = sign * (ixy / 24 - area * cx * cy);
  double deg = 0.5 * std::atan2(2 * sxy, sxx - syy) * 180 / std::numbers::pi;
  if (deg <= -90) deg += 180;
  return deg;
}

double usable_area_mm2(const Bin& hide) {
  double area = std::abs(signed_area(hide.outer));
  for (const Polygon2& hole : hide.holes) area -= std::abs(signed_area(hole));
  return area;
}

std::vector<Bin> baldacci_hides(const std::filesystem::path& file, double mm_per_unit) {
  if (!(mm_per_unit > 0)) throw EngineError("the scale of the Baldacci hides must be positive mm per unit");
  const NestInstance instance = read_nest_instance(file);
  if (instance.bins.empty()) throw EngineError(file.string() + " holds no hides");
  const auto scale = [mm_per_unit](Polygon2& ring) {
    for (Point2& p : ring.points) p *= mm_per_unit;
  };
  std::vector<Bin> hides;
  for (const Bin& source : instance.bins) {
    Bin hide = source;
    scale(hide.outer);
    for (Polygon2& hole : hide.holes) scale(hole);
    for (QualityZone& zone : hide.zones) scale(zone.shape);
    hide.name = instance.name + " hide " + std::to_string(source.id);
    hide.id = static_cast<int>(hides.size());
    hide.stock = 1;  // each Baldacci bin is one real hide
    hide.backbone_deg = principal_axis_deg(hide.outer);
    check_hide(hide, file.string() + " (" + hide.name + ")");
    hides.push_back(std::move(hide));
  }
  return hides;
}

}  // namespace lastcut::bench
