#pragma once
// Isotropic remeshing of a closed triangle mesh towards a uniform edge length, keeping the
// vertices on a given surface through a projection callback:
//   Botsch & Kobbelt, "A remeshing approach to multiresolution modeling", SGP 2004
//   (split edges > 4/3 L, collapse edges < 4/5 L, flip towards valence 6, tangential relaxation,
//   project back to the surface).
// Boundary edges and vertices are left where they are, so meshes with holes keep their holes.
#include <Eigen/Core>
#include <functional>

#include "engine/mesh/openmesh_types.hpp"

namespace lastcut {

// Maps a point near the surface (mm) to the nearest point on it (mm).
using SurfaceProjection = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

// Runs `iterations` rounds of split / collapse / flip / relax / project with target edge
// length `target_edge_mm`. Deleted elements are garbage-collected before returning.
void isotropic_remesh(OmMesh& mesh, double target_edge_mm, int iterations, const SurfaceProjection& project);

// Splits the longest or collapses the shortest edges until the mesh has `target_triangles`
// (to within one: closed meshes have an even count), then relaxes and projects `smoothing_rounds` times.
void adjust_triangle_count(OmMesh& mesh, int target_triangles, int smoothing_rounds, const SurfaceProjection& project);

}  // namespace lastcut
