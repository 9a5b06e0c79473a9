#pragma once
// Turning the labelled faces of the cut mesh into the two halves (thesis step 5): each half is the
// largest connected piece of its label with any enclosed islands absorbed, re-indexed as its own
// mesh, checked to be a topological disk (one boundary loop, Euler characteristic 1), with the
// four corners where the centre cut meets the feather line (toe, heel) and the top rim
// (top_front, top_back) marked as landmarks.
#include <string>
#include <vector>

#include "engine/core/tri_mesh.hpp"
#include "engine/core/mesh_topology.hpp"
#include "engine/segment/segment_last.hpp"

namespace lastcut {

// Columns of the vertex field matrix carried through the cuts.
enum CutField : int { kSoleField = 0, kTopField = 1, kPlaneField = 2 };

// cut: the mesh after all three cuts; topology: its connectivity; labels: #F, equal to `label` for the
// faces of this half; fields: #V x 3 (CutField columns, exactly 0 on the cut curves).
// Throws EngineError, naming the half, when it is not a disk or a corner is missing.
Segment extract_half(const TriMesh& cut, const MeshTopology& topology, const std::vector<int>& labels, int label,
                     const Eigen::MatrixXd& fields, const std::string& name);

}  // namespace lastcut
