#include "engine/mold/boundary_loops.hpp"

#include <algorithm>
#include <string>

#include "engine/core/engine_error.hpp"

namespace lastcut {

std::vector<std::vector<int>> simple_boundary_loops(const MeshTopology& topology) {
  if (topology.first_pinch_vertex >= 0)
    throw EngineError("patch boundary is not a simple loop at vertex " + std::to_string(topology.first_pinch_vertex) +
                      " (two boundary edges leave it)");
  if (topology.open_boundary_chains > 0) throw EngineError("patch boundary is open: faces disagree on their orientation");
  std::vector<std::vector<int>> loops = topology.boundary_loops;
  std::stable_sort(loops.begin(), loops.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return loops;
}

}  // namespace lastcut
