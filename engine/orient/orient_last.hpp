#pragma once
// Standing a scanned last in the canonical frame (thesis step 1, Sabaliauskas 2017, section 3.1):
// sole down on z = 0, +X from heel to toe, heel at x ~ 0, +Z up; and telling a left last from a right one.
// The medial (big-toe) side of a left last is -Y, of a right last +Y (engine/core/foot_side.hpp).
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "engine/core/foot_side.hpp"
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

struct OrientedLast {
  TriMesh mesh;                       // the scan in the canonical frame, mm
  Eigen::Affine3d scan_to_canonical;  // rigid (rotation det +1 and translation), mm
  FootSide side;
  std::vector<std::string> notes;     // what was decided and how confidently, one line each
};

// scan: V #V x 3 mm (any pose), F #F x 3 outward-oriented. Deterministic. Throws EngineError
// when the mesh is too small or flat to be a last, or when toe/heel, sole/top or left/right
// cannot be told apart with confidence.
OrientedLast orient_last(const TriMesh& scan);

}  // namespace lastcut
