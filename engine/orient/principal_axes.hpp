#pragma once
// Area-weighted principal axes of a triangulated surface: the surface (not the vertex cloud) is
// integrated, so uneven scan density does not tilt the axes.
// Second moment of one triangle with vertices a, b, c (centroid g, area A), about the origin:
//   integral of x x^T dA = A / 12 * (a a^T + b b^T + c c^T + 9 g g^T).
#include <Eigen/Core>

#include "engine/core/tri_mesh.hpp"

namespace lastcut {

struct PrincipalAxes {
  Eigen::Vector3d centroid;  // area-weighted surface centroid, mm
  Eigen::Matrix3d axes;      // columns: unit axes by decreasing spread (longest first), right-handed
  Eigen::Vector3d spread;    // standard deviation along each axis, mm
};

// mesh: V #V x 3 mm, F #F x 3. Throws EngineError when the surface has no area.
PrincipalAxes principal_axes(const TriMesh& mesh);

}  // namespace lastcut
