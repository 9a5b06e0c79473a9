#pragma once
// Standing a scanned last in the canonical frame (thesis step 1, Sabaliauskas 2017, section 3.1):
// sole down on z = 0, +X from heel to toe, heel at x ~ 0, +Z up; and telling a left last from a right one.
// The medial (big-toe) side of a left last is -Y, of a right last +Y (engine/core/foot_side.hpp).
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/foot_side.hpp"
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

struct OrientedLast {
  TriMesh mesh;                       // the scan in the canonical frame, mm; F is the scan's (so is its topology)
  Eigen::Affine3d scan_to_canonical;  // rigid (rotation det +1 and translation), mm
  FootSide side;                      // meaningless when side_unnamed (then Left, to orient the split plane)
  bool side_unnamed = false;          // a symmetric last and no side named: its halves get neutral names
  std::vector<std::string> notes;     // what was decided and how confidently, one line each
  std::vector<std::string> warnings;  // what the operator should look at (also in notes)
};

// A last is symmetric when the toe's mean Y lies within this share of the length of the heel's:
// a straight last, made for either foot, which its shape cannot tell.
constexpr double kSymmetricToeOffsetShare = 0.005;

// scan: V #V x 3 mm (any pose), F #F x 3 outward-oriented. Deterministic. Throws EngineError
// when the mesh is too small or flat to be a last, or when toe/heel or sole/top cannot be told apart
// with confidence.
// named_side: the foot the operator says the last is for. It settles a symmetric last. When the
// last's shape says otherwise (the toe clearly leans to the other foot's medial side), the shape wins
// (the halves are its geometry) and a warning says so. A symmetric last with no side named is
// oriented with side_unnamed set and a warning.
OrientedLast orient_last(const TriMesh& scan, std::optional<FootSide> named_side = std::nullopt);

}  // namespace lastcut
