#include "engine/mesh/midpoint_subdivision.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace lastcut {

TriMesh subdivide_midpoint(const TriMesh& mesh) {
  const Eigen::Index vertex_count = mesh.V.rows(), face_count = mesh.F.rows();
  std::unordered_map<uint64_t, int> midpoint_of_edge;
  midpoint_of_edge.reserve(static_cast<size_t>(face_count) * 2);
  std::vector<Eigen::RowVector3d> midpoints;
  auto midpoint = [&](int a, int b) {
    const uint64_t key = (static_cast<uint64_t>(std::min(a, b)) << 32) | static_cast<uint32_t>(std::max(a, b));
    const auto [it, inserted] = midpoint_of_edge.emplace(key, static_cast<int>(vertex_count + static_cast<Eigen::Index>(midpoints.size())));
    if (inserted) midpoints.push_back(0.5 * (mesh.V.row(a) + mesh.V.row(b)));
    return it->second;
  };
  TriMesh result;
  result.F.resize(4 * face_count, 3);
  for (Eigen::Index f = 0; f < face_count; ++f) {
    const int a = mesh.F(f, 0), b = mesh.F(f, 1), c = mesh.F(f, 2);
    const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    result.F.row(4 * f) << a, ab, ca;
    result.F.row(4 * f + 1) << ab, b, bc;
    result.F.row(4 * f + 2) << ca, bc, c;
    result.F.row(4 * f + 3) << ab, bc, ca;
  }
  result.V.resize(vertex_count + static_cast<Eigen::Index>(midpoints.size()), 3);
  result.V.topRows(vertex_count) = mesh.V;
  for (size_t k = 0; k < midpoints.size(); ++k) result.V.row(vertex_count + static_cast<Eigen::Index>(k)) = midpoints[k];
  return result;
}

}  // namespace lastcut
