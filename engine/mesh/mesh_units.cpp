#include "engine/mesh/mesh_units.hpp"

#include <cstdio>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

std::string box_text(const Eigen::Vector3d& box) {
  char text[96];
  std::snprintf(text, sizeof text, "box %.4g x %.4g x %.4g", box.x(), box.y(), box.z());
  return text;
}

UnitChoice forced(LengthUnit unit, const Eigen::Vector3d& box) {
  switch (unit) {
    case LengthUnit::Centimetre: return {10.0, "centimetres as configured (" + box_text(box) + "), scaled to mm"};
    case LengthUnit::Metre: return {1000.0, "metres as configured (" + box_text(box) + "), scaled to mm"};
    case LengthUnit::Inch: return {25.4, "inches as configured (" + box_text(box) + "), scaled to mm"};
    default: return {1.0, "millimetres as configured (" + box_text(box) + ")"};
  }
}

}  // namespace

UnitChoice choose_length_unit(const Eigen::Vector3d& box_size, LengthUnit requested) {
  if (requested != LengthUnit::Auto) return forced(requested, box_size);
  const double longest = box_size.maxCoeff();
  if (longest < 2.0) return {1000.0, "metres (" + box_text(box_size) + "), scaled to mm"};
  if (longest >= 50.0) return {1.0, "millimetres (" + box_text(box_size) + ")"};
  if (longest >= 15.0) return {10.0, "centimetres (" + box_text(box_size) + "), scaled to mm"};
  char text[160];
  std::snprintf(text, sizeof text,
                "cannot tell the length unit: the scan is %.3g units long (centimetres or inches?); set the unit explicitly",
                longest);
  throw EngineError(text);
}

}  // namespace lastcut
