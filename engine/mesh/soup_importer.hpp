#pragma once
// An OpenMesh importer that keeps exactly what the file says: a soup of points and triangles
// (polygons are fanned into triangles), with no topology and nothing dropped. OpenMesh's own
// mesh importers silently refuse non-manifold faces; intake must see them to count and report
// its repairs (mesh_repair.hpp).
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <array>
#include <vector>

namespace lastcut {

class SoupImporter : public OpenMesh::IO::BaseImporter {
 public:
  std::vector<std::array<double, 3>> points;  // as read (file units)
  std::vector<std::array<int, 3>> triangles;  // indices into points
  int polygons_fanned = 0;                    // faces with more than three corners
  int faces_with_bad_indices = 0;             // fewer than three corners or out-of-range indices
  int face_records = 0;                       // add_face calls: the file's face count

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override;
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override;
  OpenMesh::VertexHandle add_vertex() override;
  OpenMesh::FaceHandle add_face(const VHandles& corners) override;
  void set_point(OpenMesh::VertexHandle v, const OpenMesh::Vec3f& p) override;
  size_t n_vertices() const override { return points.size(); }
  size_t n_faces() const override { return triangles.size(); }
  size_t n_edges() const override { return 0; }
  bool is_triangle_mesh() const override { return false; }
  void reserve(unsigned int vertex_count, unsigned int /*edges*/, unsigned int face_count) override;

  // Attributes intake does not use: accepted and ignored.
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override { return OpenMesh::HalfedgeHandle(); }
  OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override { return OpenMesh::FaceHandle(); }
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle, const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle, const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(OpenMesh::FaceHandle, int) override {}
  void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
  void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}
};

}  // namespace lastcut
