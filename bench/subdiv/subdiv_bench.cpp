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
#include <vector>

#include "engine/lastgen/last_control_mesh.hpp"
#include "engine/subdiv/sample_surface.hpp"

namespace {

using namespace lastcut;

Eigen::Vector2d corner_parameter(int k, double t) {
  switch (k) {
    case 0: return {t, 0.0};
    case 1: return {1.0, t};
    case 2: return {1.0 - t, 1.0};
    default: return {0.0, 1.0 - t};
  }
}

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

  const QuadTopology topology = build_quad_topology(control);
  const std::vector<BezierPatch> patches = build_bezier_patches(control, topology);
  std::printf("\n| n | l_1 / mean l at valence 3: min / mean / max | at valence 4: min / mean / max |\n|---|---|---|\n");
  for (int n : {3, 4, 8}) {
    RatioStats extraordinary, regular;
    for (int h = 0; h < 4 * control.quad_count(); ++h) {
      const int v = control.Q(h / 4, h % 4);
      const int valence = topology.valence(v);
      if (valence != 3 && valence != 4) continue;
      std::vector<double> lengths;
      Eigen::Vector3d previous = control.V.row(v).transpose();
      for (int s = 0; s <= n; ++s) {
        const Eigen::Vector2d uv = corner_parameter(h % 4, static_cast<double>(s) / n);
        const Eigen::Vector3d p = patch_position(patches[static_cast<size_t>(h / 4)], uv.x(), uv.y());
        if (s > 0) lengths.push_back((p - previous).norm());
        previous = p;
      }
      double mean = 0.0;
      for (double l : lengths) mean += l / n;
      (valence == 3 ? extraordinary : regular).add(lengths.front() / mean);
    }
    std::printf("| %d | %.3f / %.3f / %.3f (%d edges) | %.3f / %.3f / %.3f (%d edges) |\n", n, extraordinary.min,
                extraordinary.sum / extraordinary.count, extraordinary.max, extraordinary.count, regular.min,
                regular.sum / regular.count, regular.max, regular.count);
  }
  return 0;
}
