#pragma once
// Which length unit a scan was saved in. Scanners and CAD tools export mm, cm, m or inches with
// nothing in the file to say so; a shoe last is 100..500 mm long, which decides most cases:
//   longest box side < 2        -> metres (a last is 0.1..0.5 m)
//   15 <= longest side < 50     -> centimetres (as inches it would be over 380 mm)
//   longest side >= 50          -> millimetres
//   2..15                       -> ambiguous (cm or inches): refused, the unit must be given
#include <Eigen/Core>
#include <string>

#include "engine/mesh/read_mesh.hpp"

namespace lastcut {

struct UnitChoice {
  double scale_to_mm = 1.0;
  std::string note;  // for IntakeReport::unit_note
};

// box_size: extent per axis in file units. Throws EngineError when Auto cannot decide.
UnitChoice choose_length_unit(const Eigen::Vector3d& box_size, LengthUnit requested);

}  // namespace lastcut
