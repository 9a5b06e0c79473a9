#pragma once
// The OpenMesh mesh type the engine uses where topology is needed (repair, remeshing), and the
// conversions from and to TriMesh. Points are double precision (mm) so that round trips are exact.
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "engine/core/tri_mesh.hpp"

namespace lastcut {

struct DoublePrecisionTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::Normal);
  EdgeAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::Normal);
  HalfedgeAttributes(OpenMesh::Attributes::PrevHalfedge);
};

using OmMesh = OpenMesh::TriMesh_ArrayKernelT<DoublePrecisionTraits>;

// Builds the halfedge mesh of a TriMesh that is already a 2-manifold (with or without boundary).
// Throws EngineError when a face cannot be added (non-manifold input): repair first.
OmMesh to_openmesh(const TriMesh& mesh);
// Copies the non-deleted vertices and faces; vertex order follows the OpenMesh indices.
TriMesh from_openmesh(const OmMesh& mesh);

}  // namespace lastcut
