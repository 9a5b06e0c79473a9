#pragma once
// What a 3D scanner adds to a perfect last: Gaussian noise (along the surface normal or in all
// three directions), small holes
// where the scanner saw nothing, and an arbitrary pose (the last lies anywhere on the scanner's
// turntable). All draws come from the caller's generator, so a seed reproduces the scan.
#include <Eigen/Geometry>
#include <functional>
#include <random>

#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// Our own uniform and Gaussian draws: std:: distributions differ between standard libraries,
// the raw mt19937_64 stream does not, so a seed gives the same scan everywhere.
double uniform01(std::mt19937_64& random);        // [0, 1)
double standard_normal(std::mt19937_64& random);  // N(0, 1), Box-Muller

// Moves every vertex along its area-weighted normal by N(0, sigma_mm^2).
void add_normal_noise(TriMesh& mesh, double sigma_mm, std::mt19937_64& random);
// Moves every vertex by N(0, sigma_mm^2) in each of x, y and z, as a scanner's point error is:
// the tangential part does not change the surface but tilts and squeezes thin triangles.
void add_isotropic_noise(TriMesh& mesh, double sigma_mm, std::mt19937_64& random);

// Removes `count` small disks of triangles (the k-ring around a random vertex, k chosen so that
// the hole is 2..8 mm across), at least 25 mm apart, only around vertices `allowed` accepts.
// Unreferenced vertices are dropped. Throws EngineError when there is no room for that many holes.
void punch_holes(TriMesh& mesh, int count, const std::function<bool(const Eigen::Vector3d&)>& allowed,
                 std::mt19937_64& random);

// A uniformly random rotation and a translation of up to 150 mm per axis.
Eigen::Affine3d random_pose(std::mt19937_64& random);

// Applies a rigid transform to the vertices (#V x 3, mm).
void transform_vertices(TriMesh& mesh, const Eigen::Affine3d& transform);

}  // namespace lastcut
