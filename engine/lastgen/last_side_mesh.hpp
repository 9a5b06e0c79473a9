#pragma once
// The quad control mesh of the last's surface without its flat top: the Bezier path's way of keeping
// the rim of the top cut a sharp edge, as on a real last (LastSurface::Bezier).
//
// The rim is made a boundary of the control mesh. With the ghost-point boundary rule of engine/subdiv
// (p_ghost = 2 v - p_inner, the Catmull-Clark boundary rule; E. Catmull and J. Clark, "Recursively
// generated B-spline surfaces on arbitrary topological meshes", Computer-Aided Design 10(6), 1978) the
// Bezier surface ends exactly on the cubic B-spline curve of the boundary polygon. All boundary control
// points lie in the cut plane, so that curve lies in the plane (a B-spline is a convex combination of
// its control points); the top is then a flat cap meshed to the same rim samples (bezier_last.hpp).
// This is the sharp boundary-crease idea of H. Hoppe et al., "Piecewise smooth surface reconstruction",
// SIGGRAPH 1994 (a crease curve is a B-spline of the crease polygon alone), with the two sides of the
// crease built as separate surfaces.
//
// Layout: the box lattice of cube_sphere.hpp cast from a spine along the last (cast_along_spine), whose
// top box face is the cap; its cells on the flat of the cut, a rectangle of cap_cells_u x cap_cells_v,
// are left out, so that the rest is a disk whose boundary loop is the rim. The rim points slide on the
// rim curve (the body, LastShape::body_value, meets the cut plane) and the others on the body during the
// area-equalising relaxation of control_relaxation.hpp; then the control points are fitted to the body
// and the rim in the least-squares sense with a fairness term (control_fit.hpp).
#include <array>

#include "engine/lastgen/last_shape.hpp"
#include "engine/subdiv/quad_mesh.hpp"

namespace lastcut {

struct LastSideMesh {
  QuadMesh control;  // open, outward, mm; every vertex used; one boundary loop: the rim, in the cut plane
  // The rim's four corners of the cap's cap_cells_u x cap_cells_v cells, in the order the side's
  // boundary half-edges run: corner 0 -> 1 is cap_cells_u control edges, 1 -> 2 cap_cells_v, and so on.
  std::array<int, 4> cap_corners{};
  int cap_cells_u = 0, cap_cells_v = 0;
  Eigen::Vector3d cut_point_mm = Eigen::Vector3d::Zero();  // a point of the cut plane and its outward
  Eigen::Vector3d cut_normal = Eigen::Vector3d::UnitZ();   // unit normal (the top of the last)
};

// The side control mesh on a box of `cells` (nx, ny, nz). Throws EngineError when the box is too
// coarse to put at least 2 x 2 cells on the top cut.
LastSideMesh last_side_mesh(const LastShape& shape, const LastParams& params, const std::array<int, 3>& cells);

// The point of the rim (the body meets the cut plane) seen from `cap_centre_mm` (on the cut, inside the
// rim) in the direction of p projected into the plane; mm. Exactly in the plane up to rounding.
Eigen::Vector3d rim_point(const LastShape& shape, const Eigen::Vector3d& cap_centre_mm, const Eigen::Vector3d& cut_normal,
                          const Eigen::Vector3d& p_mm);

}  // namespace lastcut
