// Disk check of a triangle mesh on its MeshTopology; see disk_topology.hpp.
#include "engine/flatten/disk_topology.hpp"

#include <string>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

void check_arrays(const TriMesh& mesh) {
  if (mesh.triangle_count() == 0 || mesh.vertex_count() < 3) throw EngineError("cannot flatten an empty mesh");
  if (mesh.F.cols() != 3 || mesh.V.cols() != 3) throw EngineError("mesh must have 3D vertices and triangular faces");
  if (!mesh.V.allFinite()) throw EngineError("mesh has non-finite vertex coordinates");
  for (int f = 0; f < mesh.triangle_count(); ++f) {
    const int a = mesh.F(f, 0), b = mesh.F(f, 1), c = mesh.F(f, 2);
    if (a == b || b == c || a == c) {
      throw EngineError("triangle " + std::to_string(f) + " repeats a vertex: repair the mesh first");
    }
  }
}

void check_connectivity(const TriMesh& mesh, const MeshTopology& t) {
  if (t.vertex_count() != mesh.vertex_count() || t.face_count() != mesh.triangle_count())
    throw EngineError("flatten: the mesh topology was built for another mesh");
  for (int v = 0; v < t.vertex_count(); ++v) {
    const int begin = t.out_offsets[static_cast<std::size_t>(v)], end = t.out_offsets[static_cast<std::size_t>(v) + 1];
    if (begin == end) {
      throw EngineError("vertex " + std::to_string(v) + " is not used by any triangle: remove unused vertices first");
    }
    for (int i = begin; i < end; ++i) {
      const int w = t.out_targets[static_cast<std::size_t>(i)];
      for (int j = i + 1; j < end; ++j) {
        if (t.out_targets[static_cast<std::size_t>(j)] == w) {
          throw EngineError("edge " + std::to_string(v) + "-" + std::to_string(w) +
                            " is shared by faces of the same orientation: non-manifold or flipped faces");
        }
      }
    }
    if (t.first_pinch_vertex == v) {
      throw EngineError("vertex " + std::to_string(v) + " is a non-manifold boundary vertex (two boundary fans)");
    }
  }
  int components = 0;
  face_components(t, {}, components);
  if (components != 1) {
    throw EngineError("mesh has " + std::to_string(components) + " separate pieces; flatten one piece at a time");
  }
  if (t.boundary_half_edges == 0) throw EngineError("mesh is a closed surface, not a disk: cut it into halves first");
  if (t.open_boundary_chains > 0) throw EngineError("mesh boundary does not close into a loop");
  if (t.boundary_loops.size() != 1) {
    throw EngineError("mesh has more than one boundary loop (holes): a flattening half must be a disk");
  }
  const long long euler = mesh.vertex_count() - t.edge_count() + mesh.triangle_count();
  if (euler != 1) {
    throw EngineError("mesh is not a disk (Euler characteristic " + std::to_string(euler) +
                      ", a disk has 1): it has handles");
  }
}

}  // namespace

void check_disk(const TriMesh& mesh, const MeshTopology& topology) {
  check_arrays(mesh);
  check_connectivity(mesh, topology);
}

MeshTopology check_disk(const TriMesh& mesh) {
  check_arrays(mesh);
  MeshTopology topology = build_mesh_topology(mesh.F, mesh.V.rows());
  check_connectivity(mesh, topology);
  return topology;
}

int farthest_vertex_on_loop(const TriMesh& mesh, const std::vector<int>& loop, int from) {
  int best = loop[0];
  double best_sq = -1.0;
  for (int v : loop) {
    const double d = (mesh.V.row(v) - mesh.V.row(from)).squaredNorm();
    if (d > best_sq) {
      best_sq = d;
      best = v;
    }
  }
  return best;
}

}  // namespace lastcut
