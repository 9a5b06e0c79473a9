#include "engine/lastgen/last_control_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/subdiv/sample_surface.hpp"

namespace lastcut {
namespace {

constexpr int kTypicalControlQuads = 1500;  // n grows once the control mesh has this many quads
constexpr int kFitSteps = 16;

// Where the ray centre + t * direction (t in [0, 1.5]) first leaves the solid.
Eigen::Vector3d ray_exit(const LastShape& shape, const Eigen::Vector3d& centre, const Eigen::Vector3d& direction) {
  constexpr int kSteps = 192;
  double inside = 0.0;
  for (int s = 1; s <= kSteps; ++s) {
    const double t = 1.5 * s / kSteps;
    if (shape.value(centre + t * direction) > 0.0) {
      double outside = t;
      for (int iteration = 0; iteration < 50; ++iteration) {
        const double middle = 0.5 * (inside + outside);
        (shape.value(centre + middle * direction) > 0.0 ? outside : inside) = middle;
      }
      return centre + 0.5 * (inside + outside) * direction;
    }
    inside = t;
  }
  throw EngineError("last control mesh: a ray from the centre does not leave the last");
}

}  // namespace

int bezier_detail_for(int target_triangles) {
  const double n = std::floor(std::sqrt(target_triangles / (2.0 * kTypicalControlQuads)));
  return static_cast<int>(std::clamp(n, 1.0, 8.0));
}

QuadMesh last_control_mesh(const LastShape& shape, const LastParams& params, int control_quads) {
  const auto [low, high] = shape.bounds_mm();
  // A point well inside: behind the middle (the heel part is tall), a quarter of the way up to the cut.
  const double centre_x = 0.4 * params.length_mm;
  const double sole = shape.sole_z_mm(centre_x);
  const Eigen::Vector3d centre(centre_x, 0.5 * (low.y() + high.y()), sole + 0.3 * (shape.top_cut_z_mm(centre_x) - sole));
  if (shape.value(centre) >= 0.0) throw EngineError("last control mesh: the centre is not inside the last");
  // Box proportional to the extent: 2 (xy + xz + yz) s^2 quads.
  const Eigen::Vector3d extent = high - low;
  const double s = std::sqrt(control_quads / (2.0 * (extent.x() * extent.y() + extent.x() * extent.z() + extent.y() * extent.z())));
  const std::array<int, 3> cells{std::max(2, static_cast<int>(std::lround(s * extent.x()))),
                                 std::max(2, static_cast<int>(std::lround(s * extent.y()))),
                                 std::max(2, static_cast<int>(std::lround(s * extent.z())))};
  // Lattice coordinate -> [-1, 1] with the centre at 0 (the centre is off the box middle).
  std::array<double, 3> split{};
  for (int a = 0; a < 3; ++a) split[static_cast<size_t>(a)] = cells[static_cast<size_t>(a)] * (centre(a) - low(a)) / extent(a);
  const auto direction_of = [&](const std::array<int, 3>& lattice) {
    Eigen::Vector3d cube, stretch;
    for (int a = 0; a < 3; ++a) {
      const auto i = static_cast<size_t>(a);
      const double offset = lattice[i] - split[i];
      cube(a) = offset < 0 ? offset / split[i] : offset / (cells[i] - split[i]);
      stretch(a) = offset < 0 ? centre(a) - low(a) : high(a) - centre(a);
    }
    Eigen::Vector3d warped;
    for (int a = 0; a < 3; ++a) warped(a) = std::tan(0.25 * std::numbers::pi * cube(a));
    return Eigen::Vector3d(warped.normalized().cwiseProduct(stretch));
  };

  std::map<std::array<int, 3>, int> ids;
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector4i> quads;
  const auto id_of = [&](const std::array<int, 3>& lattice) {
    const auto [it, inserted] = ids.emplace(lattice, static_cast<int>(positions.size()));
    if (inserted) positions.push_back(ray_exit(shape, centre, direction_of(lattice)));
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    for (int side : {0, cells[static_cast<size_t>(axis)]}) {
      for (int j = 0; j < cells[static_cast<size_t>(c)]; ++j) {
        for (int i = 0; i < cells[static_cast<size_t>(b)]; ++i) {
          std::array<int, 4> corner{};
          static constexpr int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            std::array<int, 3> lattice{};
            lattice[static_cast<size_t>(axis)] = side;
            lattice[static_cast<size_t>(b)] = i + di[k];
            lattice[static_cast<size_t>(c)] = j + dj[k];
            corner[static_cast<size_t>(k)] = id_of(lattice);
          }
          // b x c = +axis: counter-clockwise seen from outside on the far side, reversed on the near side.
          if (side > 0) {
            quads.emplace_back(corner[0], corner[1], corner[2], corner[3]);
          } else {
            quads.emplace_back(corner[0], corner[3], corner[2], corner[1]);
          }
        }
      }
    }
  }
  QuadMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(positions.size()), 3);
  for (size_t v = 0; v < positions.size(); ++v) mesh.V.row(static_cast<Eigen::Index>(v)) = positions[v].transpose();
  mesh.Q.resize(static_cast<Eigen::Index>(quads.size()), 4);
  for (size_t q = 0; q < quads.size(); ++q) mesh.Q.row(static_cast<Eigen::Index>(q)) = quads[q].transpose();

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

TriMesh bezier_last_surface(const LastShape& shape, const LastParams& params) {
  const int n = bezier_detail_for(params.target_triangles);
  const int control_quads = std::max(24, static_cast<int>(std::lround(params.target_triangles / (2.0 * n * n))));
  return triangulate_quads(subdivide_bezier(last_control_mesh(shape, params, control_quads), n, SampleSpread::EvenAtExtraordinary).quads);
}

}  // namespace lastcut
