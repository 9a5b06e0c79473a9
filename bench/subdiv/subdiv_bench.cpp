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

#include <CLI/CLI.hpp>

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
  int control_quads = 1500;
  CLI::App app{"Bezier subdivision on the control mesh of a generated EU 42 last: subdivide_bezier time per detail n "
               "and the sample spread at extraordinary vs regular vertices"};
  app.add_option("control_quads", control_quads, "about this many quads in the control mesh")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
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

  const QuadTopology topology = build_quad_topology(control);
  std::printf("\n| n | spread | l_1 / mean l at valence 3: min / mean / max | at valence 4: min / mean / max |\n|---|---|---|---|\n");
  for (int n : {3, 4, 8}) {
    for (SampleSpread spread : {SampleSpread::Uniform, SampleSpread::EvenAtExtraordinary}) {
      const SubdividedSurface surface = subdivide_bezier(control, n, spread);
      RatioStats extraordinary, regular;
      for (const EdgeEndSpacing& edge : edge_end_spacing(control, surface, n)) {
        for (const auto& [vertex, ratio] : {std::pair{edge.from, edge.first_ratio}, std::pair{edge.to, edge.last_ratio}}) {
          const int valence = topology.valence(vertex);
          if (valence == 3) extraordinary.add(ratio);
          if (valence == 4) regular.add(ratio);
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
