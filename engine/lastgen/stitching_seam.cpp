#include "engine/lastgen/stitching_seam.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "engine/lastgen/scan_artifacts.hpp"

namespace lastcut {
namespace {

// A unit vector in a uniformly random direction.
Eigen::Vector3d random_direction(std::mt19937_64& random) {
  Eigen::Vector3d direction;
  do {
    for (int axis = 0; axis < 3; ++axis) direction(axis) = standard_normal(random);
  } while (direction.norm() < 1e-6);
  return direction.normalized();
}

// Splits every edge that crosses the plane {x : normal . (x - point) = 0} at the crossing and each
// cut triangle into three. Returns, per vertex of the result, its side: +1, -1, or 0 on the seam.
std::vector<int> cut_along_plane(TriMesh& mesh, const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  const Eigen::Index old_count = mesh.V.rows();
  std::vector<double> height(static_cast<std::size_t>(old_count));
  for (Eigen::Index v = 0; v < old_count; ++v) {
    const double h = normal.dot(mesh.V.row(v).transpose() - point);
    height[static_cast<std::size_t>(v)] = h == 0.0 ? 1e-12 : h;  // a vertex on the plane counts as the second pass's
  }
  std::map<std::pair<int, int>, int> crossing;  // edge (low, high) -> its new vertex
  std::vector<Eigen::RowVector3d> added;
  const auto split = [&](int a, int b) {
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    if (const auto found = crossing.find(key); found != crossing.end()) return found->second;
    const double ha = height[static_cast<std::size_t>(a)], hb = height[static_cast<std::size_t>(b)];
    const double t = ha / (ha - hb);
    added.push_back((1.0 - t) * mesh.V.row(a) + t * mesh.V.row(b));
    const int index = static_cast<int>(old_count) + static_cast<int>(added.size()) - 1;
    crossing.emplace(key, index);
    return index;
  };
  std::vector<Eigen::Vector3i> faces;
  faces.reserve(static_cast<std::size_t>(mesh.F.rows()) + 64);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3i face = mesh.F.row(f);
    int lone = -1;  // the corner alone on its side, if the plane cuts the triangle
    for (int k = 0; k < 3; ++k) {
      const bool side = height[static_cast<std::size_t>(face(k))] > 0;
      if (side != (height[static_cast<std::size_t>(face((k + 1) % 3))] > 0) &&
          side != (height[static_cast<std::size_t>(face((k + 2) % 3))] > 0))
        lone = k;
    }
    if (lone < 0) {
      faces.push_back(face);
      continue;
    }
    const int a = face(lone), b = face((lone + 1) % 3), c = face((lone + 2) % 3);
    const int p = split(a, b), q = split(c, a);  // both keep the face's winding below
    faces.emplace_back(a, p, q);
    faces.emplace_back(p, b, c);
    faces.emplace_back(p, c, q);
  }
  mesh.V.conservativeResize(old_count + static_cast<Eigen::Index>(added.size()), 3);
  for (std::size_t i = 0; i < added.size(); ++i) mesh.V.row(old_count + static_cast<Eigen::Index>(i)) = added[i];
  mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) mesh.F.row(static_cast<Eigen::Index>(f)) = faces[f].transpose();
  std::vector<int> side(static_cast<std::size_t>(mesh.V.rows()), 0);
  for (Eigen::Index v = 0; v < old_count; ++v) side[static_cast<std::size_t>(v)] = height[static_cast<std::size_t>(v)] > 0 ? 1 : -1;
  return side;
}

}  // namespace

void add_stitching_seams(TriMesh& mesh, int count, double misregistration_mm, std::mt19937_64& random) {
  if (count <= 0 || mesh.V.rows() == 0) return;
  const Eigen::Vector3d centroid = mesh.V.colwise().mean().transpose();
  const Eigen::Vector3d extent = (mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff()).transpose();
  for (int seam = 0; seam < count; ++seam) {
    // Through the middle half of the last, so the seam crosses it rather than grazing an end.
    Eigen::Vector3d point = centroid;
    for (int axis = 0; axis < 3; ++axis)
      point(axis) += 0.25 * extent(axis) * (2.0 * uniform01(random) - 1.0);
    const Eigen::Vector3d normal = random_direction(random);
    const std::vector<int> side = cut_along_plane(mesh, point, normal);
    // Half the error as a turn (its lever: 100 mm, about half a last), half as a shift.
    const Eigen::AngleAxisd turn(0.5 * misregistration_mm / 100.0, random_direction(random));
    const Eigen::Vector3d shift = 0.5 * misregistration_mm * random_direction(random);
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
      const int on = side[static_cast<std::size_t>(v)];
      if (on < 0) continue;
      const Eigen::Vector3d x = mesh.V.row(v).transpose();
      const Eigen::Vector3d moved = point + turn * (x - point) + shift;
      mesh.V.row(v) = (on > 0 ? moved : 0.5 * (x + moved)).transpose();
    }
  }
}

}  // namespace lastcut
