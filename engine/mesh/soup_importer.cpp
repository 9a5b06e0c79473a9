#include "engine/mesh/soup_importer.hpp"

namespace lastcut {

OpenMesh::VertexHandle SoupImporter::add_vertex(const OpenMesh::Vec3f& p) {
  points.push_back({p[0], p[1], p[2]});
  return OpenMesh::VertexHandle(static_cast<int>(points.size()) - 1);
}

OpenMesh::VertexHandle SoupImporter::add_vertex(const OpenMesh::Vec3d& p) {
  points.push_back({p[0], p[1], p[2]});
  return OpenMesh::VertexHandle(static_cast<int>(points.size()) - 1);
}

OpenMesh::VertexHandle SoupImporter::add_vertex() {
  points.push_back({0.0, 0.0, 0.0});
  return OpenMesh::VertexHandle(static_cast<int>(points.size()) - 1);
}

void SoupImporter::set_point(OpenMesh::VertexHandle v, const OpenMesh::Vec3f& p) {
  if (v.is_valid() && static_cast<size_t>(v.idx()) < points.size()) points[static_cast<size_t>(v.idx())] = {p[0], p[1], p[2]};
}

void SoupImporter::reserve(unsigned int vertex_count, unsigned int, unsigned int face_count) {
  points.reserve(vertex_count);
  triangles.reserve(face_count);
}

OpenMesh::FaceHandle SoupImporter::add_face(const VHandles& corners) {
  ++face_records;
  const int count = static_cast<int>(points.size());
  bool valid = corners.size() >= 3;
  for (const auto& corner : corners) valid = valid && corner.is_valid() && corner.idx() < count;
  if (!valid) {
    ++faces_with_bad_indices;
    return OpenMesh::FaceHandle();
  }
  if (corners.size() > 3) ++polygons_fanned;
  for (size_t k = 1; k + 1 < corners.size(); ++k) triangles.push_back({corners[0].idx(), corners[k].idx(), corners[k + 1].idx()});
  return OpenMesh::FaceHandle(static_cast<int>(triangles.size()) - 1);
}

}  // namespace lastcut
