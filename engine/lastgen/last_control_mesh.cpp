#include "engine/lastgen/last_control_mesh.hpp"

#include "engine/lastgen/cube_sphere.hpp"
#include "engine/subdiv/sample_surface.hpp"

namespace lastcut {
namespace {

constexpr int kFitSteps = 16;

}  // namespace

QuadMesh last_control_mesh(const LastShape& shape, const LastParams& params, int control_quads) {
  const auto [low, high] = shape.bounds_mm();
  // A point well inside: behind the middle (the heel part is tall), a quarter of the way up to the cut.
  const double centre_x = 0.4 * params.length_mm;
  const double sole = shape.sole_z_mm(centre_x);
  const Eigen::Vector3d centre(centre_x, 0.5 * (low.y() + high.y()), sole + 0.3 * (shape.top_cut_z_mm(centre_x) - sole));
  QuadMesh mesh = cast_cube_sphere(shape, centre, RayBox{low, high, low, high}, cube_cells_for(high - low, control_quads)).mesh;

  // Limit positions onto the surface (n = 1 samples are exactly the patch corners).
  for (int step = 0; step < kFitSteps; ++step) {
    const Eigen::MatrixXd limit = subdivide_bezier(mesh, 1).quads.V;
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
      const Eigen::Vector3d p = limit.row(v).transpose();
      mesh.V.row(v) += (shape.project(p) - p).transpose();
    }
  }
  return mesh;
}

}  // namespace lastcut
