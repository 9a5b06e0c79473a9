#include "baldacci_hides.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "engine/core/engine_error.hpp"
#include "engine/core/polygon_centroid.hpp"
#include "engine/nest/hide_file.hpp"
#include "engine/nest/nest_json.hpp"

namespace lastcut::bench {

double principal_axis_deg(const Polygon2& outline) {
  if (!(std::abs(signed_area(outline)) > 0)) throw EngineError("a hide outline without area has no principal axis");
  const Point2 axis = principal_axis(outline);
  double deg = std::atan2(axis.y(), axis.x()) * 180 / std::numbers::pi;
  if (deg <= -90) deg += 180;  // an axis: (-90, 90]
  if (deg > 90) deg -= 180;
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
