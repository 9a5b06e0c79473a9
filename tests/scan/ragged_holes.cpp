// Ragged scan holes for tests; see ragged_holes.hpp.
#include "tests/scan/ragged_holes.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "engine/core/mesh_topology.hpp"

namespace lastcut::test {

// Removes the faces within a star-shaped outline around each centre (radius varying 50-100 % with
// nine lobes, on top of the triangles' own staircase): a ragged boundary whose
// perimeter is far longer than pi x its size across. Unreferenced vertices are dropped.
TriMesh with_ragged_holes(const TriMesh& mesh, const std::vector<HoleSpec>& holes) {
  const Eigen::MatrixXd normals = triangle_normals(mesh);
  std::vector<char> removed(static_cast<size_t>(mesh.F.rows()), 0);
  for (const HoleSpec& hole : holes) {
    Eigen::Index centre_vertex = 0;
    (mesh.V.rowwise() - hole.near_mm.transpose()).rowwise().squaredNorm().minCoeff(&centre_vertex);
    const Eigen::Vector3d centre = mesh.V.row(centre_vertex).transpose();
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
      if ((mesh.V.row(mesh.F(f, 0)).transpose() - centre).norm() < 5.0) normal += normals.row(f).transpose();
    normal.normalize();
    const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
      const Eigen::Vector3d d =
          (mesh.V.row(mesh.F(f, 0)) + mesh.V.row(mesh.F(f, 1)) + mesh.V.row(mesh.F(f, 2))).transpose() / 3.0 - centre;
      if (d.norm() > hole.across_mm) continue;  // the other side of the last
      const double angle = std::atan2(d.dot(v), d.dot(u));
      // Whole triangles go: the hole reaches about one edge length beyond the outline, hence the 1.5 mm.
      const double radius = 0.5 * (hole.across_mm - 1.5) * (0.75 + 0.25 * std::sin(9.0 * angle));
      if (std::hypot(d.dot(u), d.dot(v)) < radius) removed[f] = 1;
    }
  }
  // A vertex where the hole's edge touches itself (a pinch) joins two loops: its faces go too, until
  // every hole has one boundary loop.
  for (int round = 0; round < 100; ++round) {
    const MeshTopology topology = build_mesh_topology(mesh.F, mesh.V.rows(), removed);
    if (topology.first_pinch_vertex < 0) break;
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
      for (int k = 0; k < 3; ++k)
        if (mesh.F(f, k) == topology.first_pinch_vertex) removed[f] = 1;
  }
  // Islands of faces left between the lobes belong to the hole: keep the largest kept component only.
  std::vector<char> kept(removed.size());
  for (size_t f = 0; f < kept.size(); ++f) kept[f] = !removed[f];
  int components = 0;
  const std::vector<int> component = face_components(build_mesh_topology(mesh.F, mesh.V.rows()), kept, components);
  const std::vector<double> areas = component_areas(component, components, triangle_areas(mesh));
  const int largest = static_cast<int>(std::max_element(areas.begin(), areas.end()) - areas.begin());
  for (size_t f = 0; f < removed.size(); ++f) removed[f] = component[f] != largest;
  std::vector<int> new_index(static_cast<size_t>(mesh.V.rows()), -1);
  std::vector<Eigen::RowVector3i> faces;
  int used = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    if (removed[f]) continue;
    Eigen::RowVector3i face;
    for (int k = 0; k < 3; ++k) {
      int& index = new_index[mesh.F(f, k)];
      if (index < 0) index = used++;
      face(k) = index;
    }
    faces.push_back(face);
  }
  TriMesh holed;
  holed.V.resize(used, 3);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    if (new_index[v] >= 0) holed.V.row(new_index[v]) = mesh.V.row(v);
  holed.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) holed.F.row(static_cast<Eigen::Index>(f)) = faces[f];
  return holed;
}

std::vector<HoleSpec> side_holes(const TriMesh& last, const std::vector<double>& across_mm) {
  std::vector<HoleSpec> holes;
  const double length_mm = last.V.col(0).maxCoeff() - last.V.col(0).minCoeff();
  const double z = 0.5 * (last.V.col(2).minCoeff() + last.V.col(2).maxCoeff()) - 10.0;
  for (size_t i = 0; i < across_mm.size(); ++i) {
    const double x = last.V.col(0).minCoeff() + (0.25 + 0.25 * static_cast<double>(i)) * length_mm;
    const double y = (i % 2 == 0 ? 1.0 : -1.0) * 200.0;  // beyond the side: the nearest vertex is on it
    holes.push_back({Eigen::Vector3d(x, y, z), across_mm[i]});
  }
  return holes;
}

}  // namespace lastcut::test
