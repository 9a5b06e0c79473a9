#include "engine/lastgen/cube_sphere.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <utility>
#include <numbers>
#include <vector>

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

// The box surface's lattice points sent along their rays (origin, direction) to where they leave the solid.
CubeSphere cast_lattice(const LastShape& shape, const std::array<int, 3>& cells,
                        const std::function<std::pair<Eigen::Vector3d, Eigen::Vector3d>(const std::array<int, 3>&)>& ray_of) {
  const auto [shape_low, shape_high] = shape.bounds_mm();
  const double reach_mm = (shape_high - shape_low).norm();
  CubeSphere sphere;
  std::map<std::array<int, 3>, int> ids;
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector4i> quads;
  const auto id_of = [&](const std::array<int, 3>& lattice) {
    const auto [it, inserted] = ids.emplace(lattice, static_cast<int>(positions.size()));
    if (inserted) {
      const auto [origin, direction] = ray_of(lattice);
      positions.push_back(ray_exit(shape, origin, direction, reach_mm));
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

  return cast_lattice(shape, cells, [&](const std::array<int, 3>& lattice) { return std::pair{centre, direction_of(lattice)}; });
}


namespace {

constexpr double kSpineShare = 0.75;            // of the box's x lattice cast straight across from the spine
constexpr double kSpineBackFraction = 0.15;     // spine ends, fractions of the length
constexpr double kSpineFrontFraction = 0.85;
constexpr int kSpineStations = 33;

// Where the solid ends along `direction` from the inside point p (mm), found in 1 mm steps then bisected.
double reach_from(const LastShape& shape, const Eigen::Vector3d& p, const Eigen::Vector3d& direction) {
  double inside = 0.0, outside = 1.0;
  while (shape.value(p + outside * direction) <= 0.0) {
    inside = outside;
    outside += 1.0;
    if (outside > 1000.0) throw EngineError("last control mesh: the section does not close");
  }
  for (int iteration = 0; iteration < 40; ++iteration) {
    const double middle = 0.5 * (inside + outside);
    (shape.value(p + middle * direction) > 0.0 ? outside : inside) = middle;
  }
  return 0.5 * (inside + outside);
}

// The middle of the section at x and its half extents: {x, y centre, z centre, half width, half height}.
Eigen::Matrix<double, 5, 1> section_at(const LastShape& shape, double x_mm) {
  const Eigen::Vector3d start(x_mm, 0.0, shape.sole_z_mm(x_mm) + 6.0);
  if (shape.value(start) >= 0.0) throw EngineError("last control mesh: the spine leaves the last");
  const double up = reach_from(shape, start, Eigen::Vector3d::UnitZ()), down = reach_from(shape, start, -Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d middle(x_mm, 0.0, start.z() + 0.5 * (up - down));
  const double left = reach_from(shape, middle, Eigen::Vector3d::UnitY()), right = reach_from(shape, middle, -Eigen::Vector3d::UnitY());
  Eigen::Matrix<double, 5, 1> section;
  section << x_mm, 0.5 * (left - right), middle.z(), 0.5 * (left + right), 0.5 * (up + down);
  return section;
}

// The lattice's x stations moved so that every slab between two of them holds the same share of the long
// faces' area, measured on a first cast at `stations` (the cast costs a few hundredths of a second). The
// number of cells around a section is the same everywhere, so with evenly spaced stations the cells of
// the tall sections at the instep had twice the area of the toe's (docs/subdivision.md).
std::vector<double> equal_area_stations(const CubeSphere& cast, const std::vector<double>& stations) {
  const size_t slabs = stations.size() - 1;
  std::vector<double> area(slabs, 0.0);
  for (int q = 0; q < cast.mesh.quad_count(); ++q) {
    const auto& [axis, high_side, i, j] = cast.face_cell[static_cast<size_t>(q)];
    if (axis == 0) continue;  // the end faces belong to no slab
    const Eigen::Vector3d p0 = cast.mesh.V.row(cast.mesh.Q(q, 0)), p1 = cast.mesh.V.row(cast.mesh.Q(q, 1)),
                          p2 = cast.mesh.V.row(cast.mesh.Q(q, 2)), p3 = cast.mesh.V.row(cast.mesh.Q(q, 3));
    area[static_cast<size_t>(axis == 1 ? j : i)] += 0.5 * (p2 - p0).cross(p3 - p1).norm();  // x is c on y faces, b on z faces
  }
  // The cumulative area over the cube's x (linear within a slab), inverted at equal steps.
  std::vector<double> cumulative(slabs + 1, 0.0);
  for (size_t s = 0; s < slabs; ++s) cumulative[s + 1] = cumulative[s] + area[s];
  std::vector<double> moved(stations.size());
  size_t s = 0;
  for (size_t k = 0; k <= slabs; ++k) {
    const double target = cumulative[slabs] * static_cast<double>(k) / static_cast<double>(slabs);
    while (s + 1 < slabs && cumulative[s + 1] < target) ++s;
    const double w = (target - cumulative[s]) / (cumulative[s + 1] - cumulative[s]);
    moved[k] = stations[s] + std::clamp(w, 0.0, 1.0) * (stations[s + 1] - stations[s]);
  }
  moved.front() = stations.front(), moved.back() = stations.back();
  return moved;
}

}  // namespace

CubeSphere cast_along_spine(const LastShape& shape, const LastParams& params, const std::array<int, 3>& cells) {
  const double x_back = kSpineBackFraction * params.length_mm, x_front = kSpineFrontFraction * params.length_mm;
  std::vector<Eigen::Matrix<double, 5, 1>> stations;
  for (int s = 0; s < kSpineStations; ++s) stations.push_back(section_at(shape, x_back + (x_front - x_back) * s / (kSpineStations - 1)));
  const auto section = [&](double t) {  // t in [0, 1] along the spine
    const double at = std::clamp(t, 0.0, 1.0) * (kSpineStations - 1);
    const auto i = std::min(static_cast<size_t>(at), static_cast<size_t>(kSpineStations - 2));
    const double w = at - static_cast<double>(i);
    return Eigen::Matrix<double, 5, 1>((1 - w) * stations[i] + w * stations[i + 1]);
  };
  // The ends fan out a little beyond the heel back and the toe tip, so their rays meet the end walls.
  const double reach_back = 1.2 * x_back, reach_front = 1.2 * (params.length_mm - x_front);
  const auto cast = [&](const std::vector<double>& cube_x) {
    return cast_lattice(shape, cells, [&](const std::array<int, 3>& lattice) {
      Eigen::Vector3d cube;
      for (int a = 0; a < 3; ++a) cube(a) = 2.0 * lattice[static_cast<size_t>(a)] / cells[static_cast<size_t>(a)] - 1.0;
      cube.x() = cube_x[static_cast<size_t>(lattice[0])];
      const double along = std::clamp(cube.x() / kSpineShare, -1.0, 1.0);
      const double beyond = (cube.x() - kSpineShare * along) / (1.0 - kSpineShare);  // 0 on the spine's stretch
      const Eigen::Matrix<double, 5, 1> s = section(0.5 * (along + 1.0));
      const Eigen::Vector3d origin(s(0), s(1), s(2));
      const auto warp = [](double c) { return std::tan(0.25 * std::numbers::pi * c); };
      const Eigen::Vector3d direction(warp(beyond) * (beyond < 0 ? reach_back : reach_front), warp(cube.y()) * s(3), warp(cube.z()) * s(4));
      return std::pair{origin, direction};
    });
  };
  // Evenly spaced stations first, then the stations that give every slab along the last the same area.
  std::vector<double> cube_x(static_cast<size_t>(cells[0] + 1));
  for (size_t i = 0; i < cube_x.size(); ++i) cube_x[i] = 2.0 * static_cast<double>(i) / cells[0] - 1.0;
  return cast(equal_area_stations(cast(cube_x), cube_x));
}

}  // namespace lastcut
