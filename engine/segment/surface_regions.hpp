#pragma once
// The sole and the top cut of an oriented last as face regions (thesis step 2, Sabaliauskas 2017,
// section 3.1, eqs. 5-9): faces are classified by the elevation angle of their normal above the
// XY plane, alpha = asin(n_z / |n|) (eq. 6): sole V1 alpha <= sole angle, sides V2, top V3 alpha >= top angle.
// Scan noise is handled by classifying with normals averaged over a few rings of neighbours and by
// keeping one connected region with its small gaps filled, so each region is a disk whose boundary
// is one loop. The top is only the flat cut around the highest point, not every up-facing face:
// the toe and vamp face upwards too but belong to the halves.
#include <Eigen/Core>
#include <vector>

#include "engine/core/tri_mesh.hpp"
#include "engine/core/mesh_topology.hpp"

namespace lastcut {

// Elevation angle (rad, in [-pi/2, pi/2]) of each face's normal after `passes` rounds of
// averaging vertex normals with their neighbours. Returns #F.
Eigen::VectorXd smoothed_elevation_rad(const TriMesh& mesh, const MeshTopology& topology, double passes);

// Adds to `region` every connected piece of its complement except the one with the largest area.
void fill_region_gaps(const MeshTopology& topology, const Eigen::VectorXd& areas, std::vector<char>& region);

// The largest connected set of faces with elevation <= sole_angle_rad, joined (by a closing) with
// other down-facing pieces that lie in the lowest third of the height and have at least 2 % of
// its area, gaps filled. #F flags. Throws EngineError when no face faces down.
std::vector<char> sole_region(const TriMesh& mesh, const MeshTopology& topology, const Eigen::VectorXd& elevation_rad,
                              const Eigen::VectorXd& areas, double sole_angle_rad);

// The flat top cut: faces with elevation >= top_angle_rad connected to the highest such face and
// lying within a few millimetres of the plane fitted to them, gaps filled. #F flags.
// Throws EngineError when no face faces up.
std::vector<char> top_region(const TriMesh& mesh, const MeshTopology& topology, const Eigen::VectorXd& elevation_rad,
                             const Eigen::VectorXd& areas, double top_angle_rad);

}  // namespace lastcut
