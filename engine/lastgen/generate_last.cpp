#include "engine/lastgen/generate_last.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "engine/lastgen/bezier_last.hpp"
#include "engine/lastgen/last_shape.hpp"
#include "engine/lastgen/lofted_last.hpp"
#include "engine/lastgen/scan_artifacts.hpp"
#include "engine/lastgen/stitching_seam.hpp"
#include "engine/mesh/isotropic_remesh.hpp"
#include "engine/mesh/marching_tetrahedra.hpp"
#include "engine/mesh/midpoint_subdivision.hpp"

namespace lastcut {
namespace {

// Edge length of an equilateral mesh of `triangles` triangles covering `area_mm2`.
double edge_length_for(double area_mm2, int triangles) {
  return std::sqrt(4.0 * area_mm2 / (std::sqrt(3.0) * triangles));
}

// Large meshes: remesh a quarter (or sixteenth...) of the count, subdivide 1-to-4, project the
// new vertices and relax; far cheaper than remeshing at full density and of the same quality.
constexpr int kLargestRemeshedTriangles = 60000;

TriMesh remeshed_surface(const LastShape& shape, double shape_length_mm, int requested_triangles) {
  int levels = 0;
  int target_triangles = requested_triangles;
  while (target_triangles > kLargestRemeshedTriangles) {
    target_triangles /= 4;
    ++levels;
  }
  const auto [low, high] = shape.bounds_mm();
  SampleGrid grid;
  // About one target edge per cell (a last's area is ~ 1.06 length^2), so that the remesher starts
  // near the final density; the remesher, not the grid, resolves the fillets.
  const double estimated_area_mm2 = 1.06 * shape_length_mm * shape_length_mm;
  grid.spacing_mm = std::clamp(edge_length_for(estimated_area_mm2, target_triangles), 2.0, 6.0);
  grid.origin_mm = low;
  grid.node_count = ((high - low) / grid.spacing_mm).array().ceil().cast<int>() + 1;
  const TriMesh rough = marching_tetrahedra(grid, [&shape](const Eigen::Vector3d& p) { return shape.value(p); });

  const SurfaceProjection project = [&shape](const Eigen::Vector3d& p) { return shape.project(p); };
  OmMesh mesh = to_openmesh(rough);
  double edge_mm = edge_length_for(surface_area(rough), target_triangles);
  isotropic_remesh(mesh, edge_mm, 5, project);
  // The remesher's mean edge differs from the target by a few percent: correct once, then
  // hit the count exactly.
  edge_mm *= std::sqrt(static_cast<double>(mesh.n_faces()) / target_triangles);
  isotropic_remesh(mesh, edge_mm, 4, project);
  adjust_triangle_count(mesh, target_triangles, 3, project);
  if (levels == 0) return from_openmesh(mesh);
  TriMesh fine = from_openmesh(mesh);
  for (int level = 0; level < levels; ++level) fine = subdivide_midpoint(fine);
  for (Eigen::Index v = 0; v < fine.V.rows(); ++v) fine.V.row(v) = shape.project(fine.V.row(v).transpose()).transpose();
  mesh = to_openmesh(fine);
  adjust_triangle_count(mesh, requested_triangles, 2, project);
  return from_openmesh(mesh);
}

void mirror_y(TriMesh& mesh) {
  mesh.V.col(1) *= -1.0;
  mesh.F.col(1).swap(mesh.F.col(2));  // keep the faces counter-clockwise seen from outside
}

}  // namespace

GeneratedLast generate_last(const LastParams& params) {
  validate(params);
  const LastShape shape(params);  // medial side +Y
  GeneratedLast result;
  result.mesh = params.surface == LastSurface::Bezier   ? bezier_last_surface(shape, params)
                : params.surface == LastSurface::Lofted ? lofted_last_surface(shape, params.target_triangles)
                                                        : remeshed_surface(shape, params.length_mm, params.target_triangles);
  result.canonical_to_scan = Eigen::Affine3d::Identity();

  // Separate streams, so that asking for holes does not move the noise and vice versa.
  std::mt19937_64 hole_random(params.seed * 0x9E3779B97F4A7C15ull + 1);
  std::mt19937_64 noise_random(params.seed * 0x9E3779B97F4A7C15ull + 2);
  std::mt19937_64 pose_random(params.seed * 0x9E3779B97F4A7C15ull + 3);
  std::mt19937_64 seam_random(params.seed * 0x9E3779B97F4A7C15ull + 4);

  add_stitching_seams(result.mesh, params.seams, params.seam_step_mm, seam_random);

  // Holes stay off the top cut (its edge fillet included) and off the very ends.
  const auto hole_allowed = [&shape, &params](const Eigen::Vector3d& p) {
    return p.z() < shape.top_cut_z_mm(p.x()) - 8.0 && p.x() > 10.0 && p.x() < params.length_mm - 10.0;
  };
  punch_holes(result.mesh, params.holes, hole_allowed, hole_random);
  if (params.side == FootSide::Left) mirror_y(result.mesh);
  if (params.noise_kind == ScanNoise::Isotropic) add_isotropic_noise(result.mesh, params.noise_mm, noise_random);
  else add_normal_noise(result.mesh, params.noise_mm, noise_random);
  if (params.random_pose) {
    result.canonical_to_scan = random_pose(pose_random);
    transform_vertices(result.mesh, result.canonical_to_scan);
  }
  return result;
}

}  // namespace lastcut
