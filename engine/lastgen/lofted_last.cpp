#include "engine/lastgen/lofted_last.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

// The point of the surface farthest along `direction` (unit), found by walking on the surface
// from the ray hit `start`: each step goes along the direction's tangential part and is projected
// back; the step halves whenever it stops gaining.
Eigen::Vector3d extreme_point(const LastShape& shape, Eigen::Vector3d point, const Eigen::Vector3d& direction) {
  double step_mm = 2.0;
  while (step_mm > 1e-5) {
    const Eigen::Vector3d normal = shape.gradient(point).normalized();
    const Eigen::Vector3d tangent = direction - direction.dot(normal) * normal;
    if (tangent.norm() < 1e-9) break;
    const Eigen::Vector3d next = shape.project(point + step_mm * tangent.normalized());
    if (next.dot(direction) > point.dot(direction)) point = next;
    else step_mm *= 0.5;
  }
  return point;
}

// Where the ray from `inside` along `direction` (unit) leaves the solid: sphere tracing on the
// near-distance implicit value, then bisection of the last inside/outside bracket.
Eigen::Vector3d ray_exit(const LastShape& shape, const Eigen::Vector3d& inside, const Eigen::Vector3d& direction) {
  double inner = 0.0;
  double outer = 0.0;
  for (int step = 0; step < 2000; ++step) {
    const double value = shape.value(inside + outer * direction);
    if (value > 0.0) break;
    inner = outer;
    outer += std::max(0.9 * -value, 0.02);
    if (outer > 1000.0) throw EngineError("lofted last: a ray from a section's centre never left the solid");
  }
  for (int halving = 0; halving < 30; ++halving) {
    const double middle = 0.5 * (inner + outer);
    (shape.value(inside + middle * direction) > 0.0 ? outer : inner) = middle;
  }
  return inside + 0.5 * (inner + outer) * direction;
}

// Centre (y, z) of the section x = x_mm: the mean of the inside points of a 1.5 mm grid.
Eigen::Vector2d section_centre(const LastShape& shape, double x_mm) {
  const auto [low, high] = shape.bounds_mm();
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  int inside = 0;
  for (double y = low.y(); y <= high.y(); y += 1.5)
    for (double z = low.z(); z <= high.z(); z += 1.5)
      if (shape.value(Eigen::Vector3d(x_mm, y, z)) < 0.0) {
        sum += Eigen::Vector2d(y, z);
        ++inside;
      }
  if (inside == 0) throw EngineError("lofted last: no section of the solid at x = " + std::to_string(x_mm) + " mm");
  return sum / inside;
}

// The centre line: section centres at stations along x, from the heel pole to the toe pole.
struct CentreLine {
  std::vector<double> x_mm;
  std::vector<Eigen::Vector2d> centre;
  Eigen::Vector3d at(double x) const {
    const auto upper = std::upper_bound(x_mm.begin(), x_mm.end(), x);
    const std::size_t i = std::clamp<std::size_t>(static_cast<std::size_t>(upper - x_mm.begin()), 1, x_mm.size() - 1);
    const double t = std::clamp((x - x_mm[i - 1]) / (x_mm[i] - x_mm[i - 1]), 0.0, 1.0);
    const Eigen::Vector2d yz = (1.0 - t) * centre[i - 1] + t * centre[i];
    return {x, yz.x(), yz.y()};
  }
};

}  // namespace

TriMesh lofted_last_surface(const LastShape& shape, int target_triangles) {
  const auto [low, high] = shape.bounds_mm();
  const double middle_x = 0.5 * (low.x() + high.x());
  const Eigen::Vector2d middle_centre = section_centre(shape, middle_x);
  const Eigen::Vector3d middle(middle_x, middle_centre.x(), middle_centre.y());
  const Eigen::Vector3d back(-1, 0, 0), front(1, 0, 0);
  const Eigen::Vector3d heel = extreme_point(shape, ray_exit(shape, middle, back), back);
  const Eigen::Vector3d toe = extreme_point(shape, ray_exit(shape, middle, front), front);

  CentreLine line;
  line.x_mm.push_back(heel.x());
  line.centre.push_back({heel.y(), heel.z()});
  constexpr int kSkeletonStations = 24;
  for (int k = 0; k < kSkeletonStations; ++k) {
    const double x = heel.x() + (toe.x() - heel.x()) * (0.04 + 0.92 * k / (kSkeletonStations - 1));
    line.x_mm.push_back(x);
    line.centre.push_back(section_centre(shape, x));
  }
  line.x_mm.push_back(toe.x());
  line.centre.push_back({toe.y(), toe.z()});

  // 2 x rings x per_ring triangles; about as many points around as rings along.
  const int per_ring = std::max(16, static_cast<int>(std::lround(std::sqrt(target_triangles / 2.0))));
  const int rings = std::max(3, static_cast<int>(std::lround(target_triangles / (2.0 * per_ring))));
  TriMesh mesh;
  mesh.V.resize(2 + static_cast<Eigen::Index>(rings) * per_ring, 3);
  mesh.V.row(0) = heel.transpose();
  for (int ring = 0; ring < rings; ++ring) {
    // Cosine spacing: sections crowd at the heel and toe, as a loft's do where the surface turns.
    const double s = (ring + 1.0) / (rings + 1.0);
    const double x = heel.x() + (toe.x() - heel.x()) * 0.5 * (1.0 - std::cos(std::numbers::pi * s));
    const Eigen::Vector3d centre = line.at(x);
    if (!(shape.value(centre) < 0.0))
      throw EngineError("lofted last: the centre of the section at x = " + std::to_string(x) + " mm is outside it");
    for (int j = 0; j < per_ring; ++j) {
      const double angle = 2.0 * std::numbers::pi * j / per_ring;
      mesh.V.row(1 + ring * per_ring + j) = ray_exit(shape, centre, {0, std::cos(angle), std::sin(angle)}).transpose();
    }
  }
  const int toe_pole = 1 + rings * per_ring;
  mesh.V.row(toe_pole) = toe.transpose();

  mesh.F.resize(2 * static_cast<Eigen::Index>(rings) * per_ring, 3);
  Eigen::Index face = 0;
  const auto vertex = [per_ring](int ring, int j) { return 1 + ring * per_ring + (j % per_ring); };
  for (int j = 0; j < per_ring; ++j) {
    mesh.F.row(face++) << 0, vertex(0, j + 1), vertex(0, j);
    for (int ring = 0; ring + 1 < rings; ++ring) {
      mesh.F.row(face++) << vertex(ring, j), vertex(ring, j + 1), vertex(ring + 1, j + 1);
      mesh.F.row(face++) << vertex(ring, j), vertex(ring + 1, j + 1), vertex(ring + 1, j);
    }
    mesh.F.row(face++) << toe_pole, vertex(rings - 1, j), vertex(rings - 1, j + 1);
  }
  // Outward orientation: the enclosed volume must be positive.
  double volume6 = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    volume6 += a.dot(b.cross(c));
  }
  if (volume6 < 0.0) mesh.F.col(1).swap(mesh.F.col(2));
  return mesh;
}

}  // namespace lastcut
