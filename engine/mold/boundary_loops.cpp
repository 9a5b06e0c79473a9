#include "engine/mold/boundary_loops.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "engine/core/engine_error.hpp"

namespace lastcut {

namespace {

std::uint64_t edge_key(int from, int to) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(from)) << 32) | static_cast<std::uint32_t>(to);
}

}  // namespace

std::vector<std::vector<int>> boundary_loops(const Eigen::MatrixXi& F) {
  // A directed edge is on the boundary when its twin (to -> from) is used by no triangle.
  std::unordered_map<std::uint64_t, int> directed_count;
  directed_count.reserve(static_cast<size_t>(F.rows()) * 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++directed_count[edge_key(F(f, k), F(f, (k + 1) % 3))];

  std::unordered_map<int, int> next_on_boundary;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int from = F(f, k);
      const int to = F(f, (k + 1) % 3);
      if (directed_count.count(edge_key(to, from))) continue;
      if (!next_on_boundary.emplace(from, to).second)
        throw EngineError("patch boundary is not a simple loop at vertex " + std::to_string(from) +
                          " (two boundary edges leave it)");
    }
  }

  std::vector<std::vector<int>> loops;
  std::unordered_map<int, bool> visited;
  // Start from the smallest vertex index of each loop so the result is deterministic.
  std::vector<int> starts;
  starts.reserve(next_on_boundary.size());
  for (const auto& [from, to] : next_on_boundary) starts.push_back(from);
  std::sort(starts.begin(), starts.end());
  for (int start : starts) {
    if (visited[start]) continue;
    std::vector<int> loop;
    int v = start;
    while (!visited[v]) {
      visited[v] = true;
      loop.push_back(v);
      const auto next = next_on_boundary.find(v);
      if (next == next_on_boundary.end())
        throw EngineError("patch boundary is open at vertex " + std::to_string(v));
      v = next->second;
    }
    if (v != start) throw EngineError("patch boundary loops touch at vertex " + std::to_string(v));
    loops.push_back(std::move(loop));
  }
  std::stable_sort(loops.begin(), loops.end(),
                   [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return loops;
}

}  // namespace lastcut
