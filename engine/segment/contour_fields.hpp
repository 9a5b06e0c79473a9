#pragma once
// Scalar fields on the vertices of an oriented last whose zero level sets are the feather line and
// the top rim, found by geometry instead of by the normal angle alone: a threshold on the normal
// elevation (thesis eqs. 7-9) is reached only gradually where the surface turns slowly, as in the
// arch, so noise and sampling would move the curve by millimetres.
//  - Top rim: the top cut is a plane. It is fitted (least squares, then refitted on the faces that
//    lie close to it) to the V3 top region, and the rim is where the surface has dropped a fixed
//    depth below that plane.
//  - Feather line: the sole is a smooth height field z = s(x, y) (heel pitch, arch, toe spring,
//    crown). Cubic B-splines along the last with a second-difference penalty (P-splines, Eilers &
//    Marx 1996) plus a crown quadratic across it are fitted to the V1 sole region, robustly
//    (refitted on the points within 2, 1, then 0.6 mm of the previous fit, which drops the feather
//    edge's rounding), and the feather line is where the surface has risen a fixed height above it. Both are lengths in mm measured on the surface's
//    own shape, so the curves do not depend on the triangle density, and scanner noise only enters
//    through a fit over thousands of points.
// Each field is positive inside its region, and vertices of positive field that are not connected
// to the classified region (through positive vertices) are set negative, so the level set is one
// loop around the sole or the top.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "engine/core/tri_mesh.hpp"
#include "engine/core/mesh_topology.hpp"

namespace lastcut {

struct ContourField {
  Eigen::VectorXd values;  // #V, mm: > 0 inside the sole or top region, 0 on the curve
  double fit_rms_mm = 0;   // RMS distance of the fitted points from the fitted sole surface or plane
};

// Area-weighted moving average of a vertex field (eq. 22 applied on the surface): each pass averages
// vertices to faces and back, weighted by face area, so it does not lean towards denser parts of the
// mesh; a fractional last pass moves only that share of the way. values #V, areas #F (mm^2).
Eigen::VectorXd smooth_vertex_field(const TriMesh& mesh, const Eigen::VectorXd& areas, Eigen::VectorXd values,
                                    double passes);
// The same, but the vertices of the faces flagged in plane_faces (#F; the flat top cut) average over
// those faces only: a sharp rim is a crease the average must not cross, or the larger side faces drag
// the rim's own vertices below the curve (docs/subdivision.md). Faces off the plane still see them.
Eigen::VectorXd smooth_vertex_field(const TriMesh& mesh, const Eigen::VectorXd& areas, Eigen::VectorXd values, double passes,
                                    const std::vector<char>& plane_faces);

// depth_mm below the plane fitted to `top` (#F flags): field = signed height above the plane + depth_mm
// (mm), #V. Returns nothing when the region is too small or not flat (RMS distance to the plane
// above max_rms_mm), so the caller keeps the classification.
std::optional<ContourField> top_plane_field(const TriMesh& mesh, const MeshTopology& topology, const std::vector<char>& top,
                                               const Eigen::VectorXd& areas, double depth_mm, double max_rms_mm);

// height_mm above the height field fitted to `sole` (#F flags): field = height_mm - (z - s(x, y))
// (mm), #V. Returns nothing when the fit is poor (RMS residual above max_rms_mm, e.g. the toes of
// a foot scan), so the caller keeps the classification.
std::optional<ContourField> sole_height_field(const TriMesh& mesh, const MeshTopology& topology,
                                                 const std::vector<char>& sole, const Eigen::VectorXd& areas,
                                                 double height_mm, double max_rms_mm);

}  // namespace lastcut
