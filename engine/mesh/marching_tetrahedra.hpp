#pragma once
// Polygonises the zero level set of a scalar field sampled on a regular grid by marching
// tetrahedra (each cube cut into the 6 Kuhn tetrahedra around its main diagonal, so that the
// cut is consistent between neighbouring cubes). The result is a closed, consistently oriented
// 2-manifold whose normals point towards positive values (outside), as long as the field is
// positive on the whole grid boundary. Triangles are of uneven quality: remesh afterwards.
//   Treece, Prager & Gee, "Regularised marching tetrahedra: improved iso-surface extraction",
//   Computers & Graphics 23(4), 1999 (the tetrahedral decomposition; no regularisation here).
#include <Eigen/Core>
#include <functional>

#include "engine/core/tri_mesh.hpp"

namespace lastcut {

struct SampleGrid {
  Eigen::Vector3d origin_mm = Eigen::Vector3d::Zero();  // position of node (0, 0, 0)
  double spacing_mm = 1.0;                              // cube edge length
  Eigen::Vector3i node_count = Eigen::Vector3i::Ones(); // nodes per axis (>= 2)
};

// field(p) < 0 inside, > 0 outside, p in mm. Throws EngineError when the surface reaches the
// grid boundary or the grid is empty.
TriMesh marching_tetrahedra(const SampleGrid& grid, const std::function<double(const Eigen::Vector3d&)>& field);

}  // namespace lastcut
