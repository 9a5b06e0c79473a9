#include "engine/mesh/openmesh_types.hpp"

#include <string>
#include <vector>

#include "engine/core/engine_error.hpp"

namespace lastcut {

OmMesh to_openmesh(const TriMesh& mesh) {
  OmMesh om;
  om.reserve(static_cast<size_t>(mesh.V.rows()), static_cast<size_t>(mesh.F.rows()) * 3 / 2 + 3,
             static_cast<size_t>(mesh.F.rows()));
  std::vector<OmMesh::VertexHandle> handles(static_cast<size_t>(mesh.V.rows()));
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    handles[static_cast<size_t>(v)] = om.add_vertex(OmMesh::Point(mesh.V(v, 0), mesh.V(v, 1), mesh.V(v, 2)));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const auto face = om.add_face(handles[static_cast<size_t>(mesh.F(f, 0))], handles[static_cast<size_t>(mesh.F(f, 1))],
                                  handles[static_cast<size_t>(mesh.F(f, 2))]);
    if (!face.is_valid())
      throw EngineError("mesh is not a 2-manifold at triangle " + std::to_string(f) + " (repair it first)");
  }
  return om;
}

TriMesh from_openmesh(const OmMesh& om) {
  TriMesh mesh;
  std::vector<int> new_index(om.n_vertices(), -1);
  int vertex_count = 0;
  for (const auto vh : om.vertices()) new_index[vh.idx()] = vertex_count++;
  mesh.V.resize(vertex_count, 3);
  for (const auto vh : om.vertices()) {
    const auto& p = om.point(vh);
    mesh.V.row(new_index[vh.idx()]) << p[0], p[1], p[2];
  }
  int face_count = 0;
  for ([[maybe_unused]] const auto fh : om.faces()) ++face_count;
  mesh.F.resize(face_count, 3);
  int row = 0;
  for (const auto fh : om.faces()) {
    int corner = 0;
    for (const auto vh : om.fv_range(fh)) mesh.F(row, corner++) = new_index[vh.idx()];
    ++row;
  }
  return mesh;
}

}  // namespace lastcut
