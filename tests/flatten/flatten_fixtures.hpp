#pragma once
// Test and benchmark meshes for flattening: developable patches with a known development, an OFF reader
// for the shared reference half, and 1-to-4 midpoint subdivision to make bigger halves.
#include <Eigen/Core>
#include <filesystem>

#include "engine/core/tri_mesh.hpp"

namespace lastcut::testing {

// A mesh and its exact development (the isometric flattening of that very polyhedral surface).
struct DevelopablePatch {
  TriMesh mesh;                 // mm
  Eigen::MatrixXd development;  // #V x 2, mm
};

// Cylinder of radius_mm, `around` x `along` quads over sweep_deg of arc and length_mm, vertices on the
// cylinder at non-uniform angular and axial spacing (so the triangulation is not a regular grid), quads
// split along alternating diagonals. Each quad is a planar rectangle, so the mesh is exactly developable:
// its development lays the chords side by side.
DevelopablePatch cylinder_patch(double radius_mm, double sweep_deg, double length_mm, int around, int along);

// Truncated cone patch with apex at the origin: rulings at non-uniform angles over sweep_deg, distances
// from the apex from slant_min_mm to slant_max_mm, alternating diagonals. Each quad lies in the plane of
// two rulings, so the mesh is exactly developable: rulings become rays at the 3D angles between them.
DevelopablePatch cone_patch(double half_angle_deg, double sweep_deg, double slant_min_mm, double slant_max_mm,
                            int around, int along);

// OFF file (vertices scaled by `scale`, e.g. 1000 for metres to mm). Throws EngineError when unreadable.
TriMesh read_off(const std::filesystem::path& path, double scale);

// 1-to-4 midpoint subdivision (4x triangles, geometry unchanged).
TriMesh subdivide_midpoint(const TriMesh& mesh);

// The 10 mm square in the plane z = 0 as two triangles (0, 1, 2) and (0, 2, 3), counter-clockwise.
TriMesh square_10mm();

// Spherical cap of radius_mm up to polar angle cap_deg, as a ring grid with a fan at the pole (a disk, mm).
TriMesh spherical_cap(double radius_mm, double cap_deg, int rings, int around);

// A sector of an annulus (radii r_in..r_out) over sweep_deg > 360, lifted along z by pitch_mm per turn: a
// disk-topology ramp whose metric is close to flat (ds^2 = dr^2 + (r^2 + h^2) dtheta^2 with h = pitch / 2 pi,
// h/r_in = 0.08), so its near-isometric flattening is an annulus sector that overlaps itself by
// sweep - 360 degrees. Quads split along alternating diagonals, counter-clockwise seen from above.
TriMesh helicoidal_ramp(double r_in_mm, double r_out_mm, double sweep_deg, double pitch_mm, int radial, int around);

// Least-squares rigid alignment (rotation + translation, no scaling; Procrustes/Kabsch) of `moving` onto
// `target` (both #V x 2); returns the largest point distance after alignment (mm).
double max_distance_after_rigid_alignment(const Eigen::MatrixXd& moving, const Eigen::MatrixXd& target);
// The root mean square of the same distances.
double rms_distance_after_rigid_alignment(const Eigen::MatrixXd& moving, const Eigen::MatrixXd& target);

}  // namespace lastcut::testing
