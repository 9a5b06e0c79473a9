#pragma once
// The control points of a Bezier surface fitted to a solid in the least-squares sense, with a fairness
// term: the surface of engine/subdiv is linear in its control points (bezier_patch_weights), so the
// control points that bring s x s samples per control face (plus every limit corner) closest to their
// foot points on the solid, among fair control nets, are one sparse linear solve. Foot points move
// with the surface, so the solve is repeated a few times with the same factor (Gauss-Newton on the
// squared distance to the solid, the foot points as the targets: the "point to point" step of
// W. Wang, H. Pottmann, Y. Liu, "Fitting B-spline curves to point clouds by curvature-based squared
// distance minimization", ACM TOG 25(2), 2006, which calls it PDM).
// The fairness term is a thin-plate energy of the control net, sum over vertices of |L V|^2 with L the
// uniform umbrella Laplacian (boundary vertices: along the boundary only), as in the smoothing terms
// of fitting with subdivision surfaces (H. Hoppe et al., "Piecewise smooth surface reconstruction",
// SIGGRAPH 1994). Interpolating the solid at every control vertex instead (a fixed-point iteration)
// makes the surface ring between the vertices where the solid bends more sharply than the control
// spacing can follow (the 4 mm feather fillet at ~7 mm spacing: docs/subdivision.md).
#include <functional>

#include "engine/subdiv/quad_mesh.hpp"

namespace lastcut {

struct ControlFitTargets {
  // The foot point on the solid of a sample that is not on the control mesh's boundary (mm in, mm out).
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> onto_surface;
  // The foot point of a sample on the boundary (the rim), mm.
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> onto_rim;
  // The weight of a sample's squared distance given its position and its foot point (mm; 1 =
  // ordinary; heavier where the surface must hold, e.g. on the ground or where it dips below it).
  // Asked again at every step; a weight only grows (the largest asked so far counts), and the normal
  // equations are factored again when one does.
  std::function<double(const Eigen::Vector3d& position, const Eigen::Vector3d& foot)> weight;
};

struct ControlFitOptions {
  int samples_per_edge = 3;  // s: s x s samples per control face, at the cell centres of an s x s grid
  double fairness = 0.05;    // weight of |L V|^2 against one sample's squared distance
  int iterations = 8;        // Gauss-Newton steps
};

// control V #V x 3 (mm) moved in place; Q unchanged. Throws EngineError when the normal equations are
// singular (a control vertex no sample depends on).
void fit_control_least_squares(QuadMesh& control, const QuadTopology& topology, const ControlFitTargets& targets,
                               const ControlFitOptions& options);

}  // namespace lastcut
