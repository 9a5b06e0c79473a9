#pragma once
// Cutting a triangle mesh along the zero level set of a piecewise-linear vertex field, so that a
// smooth curve becomes a chain of mesh edges instead of a staircase of whole triangles.
// Each edge whose end values have strictly opposite signs gets a new vertex at the linear zero
// crossing (shared by both faces of the edge); each crossed triangle is replaced by the triangle
// and the quad on either side (the quad split along its shorter diagonal). A crossing closer than
// snap_fraction of the edge length to an end vertex instead puts that vertex on the level set
// (its value becomes 0), which avoids sliver triangles; the curve moves by at most that fraction
// of an edge.
#include <Eigen/Core>

#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// mesh: V #V x 3 mm, F #F x 3 (updated in place). fields: #V x k vertex values; every column is
// linearly interpolated to the new vertices and the cut column is exactly 0 on the cut.
// snap_fraction in [0, 0.5).
void cut_along_zero_level(TriMesh& mesh, Eigen::MatrixXd& fields, int column, double snap_fraction);

// The snapping step of cut_along_zero_level alone: values (#V) of a field on the faces F (#F x 3)
// are set to 0 at the vertices a crossing lies within snap_fraction of an edge from. The cut then
// follows the zero level set of the piecewise-linear field with these values.
void snap_to_zero_level(const Eigen::MatrixXi& F, Eigen::Ref<Eigen::VectorXd> values, double snap_fraction);

}  // namespace lastcut
