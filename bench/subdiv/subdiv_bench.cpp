// Bezier subdivision figures on the quad control mesh of a generated EU 42 last (last_control_mesh):
// time of subdivide_bezier per detail n, and how evenly the samples are spread along the control edges
// that leave an extraordinary vertex compared with those leaving a regular one.
//   build/bin/bench_subdiv [control_quads]
// Evenness: along a control edge the n sample segments have lengths l_1 (at the vertex) .. l_n;
// the table gives l_1 / mean(l) over the edges leaving valence-3 vertices and valence-4 vertices.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "engine/lastgen/last_control_mesh.hpp"
#include "engine/subdiv/sample_surface.hpp"

namespace {

using namespace lastcut;

struct RatioStats {
  double min = 1e9, max = 0.0, sum = 0.0;
  int count = 0;
  void add(double r) {
    min = std::min(min, r), max = std::max(max, r), sum += r, ++count;
  }
};

}  // namespace

int main(int argc, char** argv) {
  const int control_quads = argc > 1 ? std::stoi(argv[1]) : 1500;
  const LastParams params = LastParams::for_eu_size(42, FootSide::Right);
  const LastShape shape(params);
  const auto build_start = std::chrono::steady_clock::now();
  const QuadMesh control = last_control_mesh(shape, params, control_quads);
  const double build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - build_start).count();
  std::printf("control mesh: %d quads, %d vertices, built and fitted in %.3f s\n\n", control.quad_count(), control.vertex_count(), build_s);

  std::printf("| n | quads | vertices | subdivide (median of 5) |\n|---|---|---|---|\n");
  for (int n = 1; n <= 8; ++n) {
    std::vector<double> times;
    SubdividedSurface surface;
    for (int run = 0; run < 5; ++run) {
      const auto start = std::chrono::steady_clock::now();
      surface = subdivide_bezier(control, n);
      times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    std::printf("| %d | %d | %d | %.4f s |\n", n, surface.quads.quad_count(), surface.quads.vertex_count(), times[2]);
  }

  // Sample segments along every control edge, read from the sampled mesh (corners first, then n - 1
  // samples per edge in the order of QuadTopology's edges, running along the edge's representative half-edge).
  const QuadTopology topology = build_quad_topology(control);
  std::printf("\n| n | spread | l_1 / mean l at valence 3: min / mean / max | at valence 4: min / mean / max |\n|---|---|---|---|\n");
  for (int n : {3, 4, 8}) {
    for (SampleSpread spread : {SampleSpread::Uniform, SampleSpread::EvenAtExtraordinary}) {
      const SubdividedSurface surface = subdivide_bezier(control, n, spread);
      RatioStats extraordinary, regular;
      for (int e = 0; e < topology.edge_count(); ++e) {
        const int h = topology.edge_half_edge[static_cast<size_t>(e)];
        const int from = control.Q(h / 4, h % 4), to = control.Q(h / 4, (h + 1) % 4);
        std::vector<Eigen::Vector3d> points{surface.quads.V.row(from).transpose()};
        for (int s = 1; s < n; ++s) points.push_back(surface.quads.V.row(control.vertex_count() + e * (n - 1) + s - 1).transpose());
        points.push_back(surface.quads.V.row(to).transpose());
        double mean = 0.0;
        for (int s = 0; s < n; ++s) mean += (points[static_cast<size_t>(s + 1)] - points[static_cast<size_t>(s)]).norm() / n;
        const double first = (points[1] - points[0]).norm(), last = (points[static_cast<size_t>(n)] - points[static_cast<size_t>(n - 1)]).norm();
        for (const auto& [vertex, length] : {std::pair{from, first}, std::pair{to, last}}) {
          const int valence = topology.valence(vertex);
          if (valence == 3) extraordinary.add(length / mean);
          if (valence == 4) regular.add(length / mean);
        }
      }
      std::printf("| %d | %s | %.3f / %.3f / %.3f (%d edges) | %.3f / %.3f / %.3f (%d edges) |\n", n,
                  spread == SampleSpread::Uniform ? "uniform" : "even at EV", extraordinary.min,
                  extraordinary.sum / extraordinary.count, extraordinary.max, extraordinary.count, regular.min,
                  regular.sum / regular.count, regular.max, regular.count);
    }
  }
  return 0;
}
