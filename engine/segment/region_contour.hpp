#pragma once
// The closed contour around a face region and its smoothing (thesis steps 2 and 5,
// Sabaliauskas 2017, section 3.1, eqs. 10-13 and 22).
// The contour graph holds the mesh edges between a region face and a face outside it (the vertices
// shared by V1 and V2, or V2 and V3). One of its edges {u, v} is removed, Dijkstra's shortest path
// from u to v is found in what is left, and the edge closes the path into a loop. Pinched or
// doubled spots of a noisy boundary are thus bridged by the shortest way round.
#include <Eigen/Core>
#include <vector>

#include "engine/core/tri_mesh.hpp"
#include "engine/core/mesh_topology.hpp"

namespace lastcut {

// region: #F flags. Returns the loop's vertex indices (first vertex not repeated), starting at the
// contour edge with the smallest x (the heel end) so the result is deterministic.
// Throws EngineError when the region has no closed boundary.
std::vector<int> region_boundary_loop(const TriMesh& mesh, const MeshTopology& topology, const std::vector<char>& region);

// Moving average of eq. 22 on a closed polyline, P*_v = P_v / 2 + (P_prev + P_next) / 4, `passes` times,
// after resampling the loop at equal arc-length steps of about spacing_mm: the passes then smooth
// over the same distance in mm whatever the vertex spacing of the scan.
// points: closed loop, mm (first point not repeated). spacing_mm > 0.
std::vector<Eigen::Vector3d> smooth_closed_polyline(const std::vector<Eigen::Vector3d>& points, int passes,
                                                    double spacing_mm);

}  // namespace lastcut
