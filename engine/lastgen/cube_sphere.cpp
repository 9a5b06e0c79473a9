#include "engine/lastgen/cube_sphere.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

// Where the ray from centre along `direction` first leaves the solid, searched up to reach_mm.
Eigen::Vector3d ray_exit(const LastShape& shape, const Eigen::Vector3d& centre, const Eigen::Vector3d& direction, double reach_mm) {
  constexpr int kSteps = 384;
  const Eigen::Vector3d unit = direction.normalized();
  double inside = 0.0;
  for (int s = 1; s <= kSteps; ++s) {
    const double t = reach_mm * s / kSteps;
    if (shape.value(centre + t * unit) > 0.0) {
      double outside = t;
      for (int iteration = 0; iteration < 50; ++iteration) {
        const double middle = 0.5 * (inside + outside);
        (shape.value(centre + middle * unit) > 0.0 ? outside : inside) = middle;
      }
      return centre + 0.5 * (inside + outside) * unit;
    }
    inside = t;
  }
  throw EngineError("last control mesh: a ray from the centre does not leave the last");
}

}  // namespace

std::array<int, 3> cube_cells_for(const Eigen::Vector3d& extent, int control_quads) {
  // 2 (xy + xz + yz) s^2 quads.
  const double s = std::sqrt(control_quads / (2.0 * (extent.x() * extent.y() + extent.x() * extent.z() + extent.y() * extent.z())));
  return {std::max(2, static_cast<int>(std::lround(s * extent.x()))), std::max(2, static_cast<int>(std::lround(s * extent.y()))),
          std::max(2, static_cast<int>(std::lround(s * extent.z())))};
}

CubeSphere cast_cube_sphere(const LastShape& shape, const Eigen::Vector3d& centre, const RayBox& box,
                            const std::array<int, 3>& cells) {
  const Eigen::Vector3d& low = box.low;
  const Eigen::Vector3d& high = box.high;
  if (shape.value(centre) >= 0.0) throw EngineError("last control mesh: the centre is not inside the last");
  const Eigen::Vector3d extent = high - low;
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
    const double up = std::max(0.0, cube(2));
    for (int a = 0; a < 2; ++a) {
      const double top = cube(a) < 0 ? centre(a) - box.top_low(a) : box.top_high(a) - centre(a);
      stretch(a) = (1.0 - up) * stretch(a) + up * top;
    }
    Eigen::Vector3d warped;
    for (int a = 0; a < 3; ++a) warped(a) = std::tan(0.25 * std::numbers::pi * cube(a));
    return Eigen::Vector3d(warped.normalized().cwiseProduct(stretch));
  };

  const auto [shape_low, shape_high] = shape.bounds_mm();
  const double reach_mm = (shape_high - shape_low).norm();
  CubeSphere sphere;
  std::map<std::array<int, 3>, int> ids;
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector4i> quads;
  const auto id_of = [&](const std::array<int, 3>& lattice) {
    const auto [it, inserted] = ids.emplace(lattice, static_cast<int>(positions.size()));
    if (inserted) {
      positions.push_back(ray_exit(shape, centre, direction_of(lattice), reach_mm));
      sphere.lattice.push_back(lattice);
    }
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
          sphere.face_cell.push_back({axis, side > 0 ? 1 : 0, i, j});
        }
      }
    }
  }
  sphere.mesh.V.resize(static_cast<Eigen::Index>(positions.size()), 3);
  for (size_t v = 0; v < positions.size(); ++v) sphere.mesh.V.row(static_cast<Eigen::Index>(v)) = positions[v].transpose();
  sphere.mesh.Q.resize(static_cast<Eigen::Index>(quads.size()), 4);
  for (size_t q = 0; q < quads.size(); ++q) sphere.mesh.Q.row(static_cast<Eigen::Index>(q)) = quads[q].transpose();
  return sphere;
}

}  // namespace lastcut
