#pragma once
// Adjacency of a triangle mesh for the segmentation steps: faces across edges (for flood fills and
// connected regions) and vertex neighbours (for Dijkstra and the moving average of eq. 22).
#include <Eigen/Core>
#include <vector>

#include "engine/core/tri_mesh.hpp"

namespace lastcut {

struct MeshGraph {
  Eigen::MatrixXi face_neighbors;  // #F x 3: face across edge F(f,k) -> F(f,(k+1)%3); -1 on a boundary or non-manifold edge
  std::vector<int> neighbor_offsets;  // #V + 1: vertex v's neighbours are neighbors[offsets[v] .. offsets[v+1])
  std::vector<int> neighbors;         // sorted per vertex
};

// mesh: V #V x 3, F #F x 3. Linear time (vertex degrees are small).
MeshGraph build_mesh_graph(const TriMesh& mesh);

// Connected components (across shared edges) of the faces with in_set[f] != 0.
// Returns #F component ids (-1 for faces outside the set), numbered in order of their lowest face.
std::vector<int> face_components(const MeshGraph& graph, const std::vector<char>& in_set, int& component_count);

// Sum of areas (mm^2) per component id; areas #F.
std::vector<double> component_areas(const std::vector<int>& component, int component_count, const Eigen::VectorXd& areas);

}  // namespace lastcut
