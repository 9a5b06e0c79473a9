// How even the Bezier last's triangles are (docs/subdivision.md, "The sample last"): the spread of the
// triangle areas (the bound of GeneratedLastTest at 5000 triangles: max / min < 8), where the smallest
// and largest sit, and the widest one-ring hole a simulated scan can punch (SimulatedScan at 12000
// triangles: < 12 mm across), with the generation time.
//   build/bin/bench_last_layout [triangles] [eu_size|0 for the default last] [right|left]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "engine/lastgen/generate_last.hpp"
#include "engine/lastgen/last_shape.hpp"

namespace {

using namespace lastcut;

Eigen::Vector3d centroid(const TriMesh& mesh, Eigen::Index f) {
  return (mesh.V.row(mesh.F(f, 0)) + mesh.V.row(mesh.F(f, 1)) + mesh.V.row(mesh.F(f, 2))).transpose() / 3.0;
}

}  // namespace

int main(int argc, char** argv) {
  int triangles = 5000;
  int eu = 0;
  std::string side_name = "right";
  CLI::App app{"How even the Bezier last's triangles are: area spread, where the smallest and largest sit, the "
               "widest one-ring hole a simulated scan can punch, generation time"};
  app.add_option("triangles", triangles, "target triangle count of the last")
      ->capture_default_str()
      ->check(CLI::Range(2000, 2'000'000));
  app.add_option("eu_size", eu, "EU size of the last (35..47), 0 for the default last")
      ->capture_default_str()
      ->check(CLI::Range(35, 47) | CLI::IsMember({0}));
  app.add_option("side", side_name, "foot side")->capture_default_str()->check(CLI::IsMember({"right", "left"}));
  CLI11_PARSE(app, argc, argv);
  const FootSide side = side_name == "left" ? FootSide::Left : FootSide::Right;
  LastParams params = eu > 0 ? LastParams::for_eu_size(eu, side) : LastParams{};
  params.side = side;
  params.target_triangles = triangles;
  params.surface = LastSurface::Bezier;
  const auto start = std::chrono::steady_clock::now();
  const TriMesh mesh = generate_last(params).mesh;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const LastShape shape(params);

  const Eigen::VectorXd areas = triangle_areas(mesh);
  std::vector<Eigen::Index> order(static_cast<size_t>(areas.size()));
  for (Eigen::Index f = 0; f < areas.size(); ++f) order[static_cast<size_t>(f)] = f;
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return areas(a) < areas(b); });
  const auto area_at = [&](double share) { return areas(order[static_cast<size_t>(share * static_cast<double>(order.size() - 1))]); };
  std::printf("%lld triangles in %.3f s; areas %.2f .. %.2f mm^2 (%.2f : 1), 1st..99th percentile %.2f .. %.2f (%.2f : 1), mean %.2f\n",
              static_cast<long long>(mesh.F.rows()), seconds, area_at(0), area_at(1), area_at(1) / area_at(0), area_at(0.01),
              area_at(0.99), area_at(0.99) / area_at(0.01), areas.mean());
  // The flat cap's triangles (all three corners in the cut plane) against the side's.
  const Eigen::Vector3d cut_normal = shape.top_cut_normal(), cut_point(0.0, 0.0, shape.top_cut_z_mm(0.0));
  double cap_area = 0.0, side_area = 0.0;
  int cap_count = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    bool on_cut = true;
    for (int c = 0; c < 3; ++c) on_cut = on_cut && std::abs((mesh.V.row(mesh.F(f, c)).transpose() - cut_point).dot(cut_normal)) < 1e-6;
    (on_cut ? cap_area : side_area) += areas(f);
    cap_count += on_cut ? 1 : 0;
  }
  std::printf("cap: %d triangles, %.0f mm^2 (%.2f %% of the area), mean %.2f mm^2; side mean %.2f mm^2\n", cap_count, cap_area,
              100.0 * cap_area / (cap_area + side_area), cap_area / std::max(1, cap_count),
              side_area / static_cast<double>(mesh.F.rows() - cap_count));
  const double sign = side == FootSide::Left ? -1.0 : 1.0;  // report in the canonical (right) frame
  for (int k = 0; k < 4; ++k) {
    const Eigen::Index small = order[static_cast<size_t>(k)], large = order[order.size() - 1 - static_cast<size_t>(k)];
    const Eigen::Vector3d a = centroid(mesh, small), b = centroid(mesh, large);
    std::printf("  small %.2f at (%.1f, %.1f, %.1f)   large %.2f at (%.1f, %.1f, %.1f)\n", areas(small), a.x(), sign * a.y(), a.z(),
                areas(large), b.x(), sign * b.y(), b.z());
  }
  // Mean side area per tenth of the length, below / above the middle height of the section.
  std::printf("mean side triangle area per tenth of the length (lower half | upper half):\n ");
  for (int band = 0; band < 10; ++band) {
    double sum[2] = {0, 0};
    int count[2] = {0, 0};
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
      const Eigen::Vector3d c = centroid(mesh, f);
      if (static_cast<int>(10.0 * c.x() / params.length_mm) != band || c.z() > shape.top_cut_z_mm(c.x()) - 1e-6) continue;
      const int upper = c.z() > 0.5 * shape.top_cut_z_mm(c.x()) ? 1 : 0;
      sum[upper] += areas(f), ++count[upper];
    }
    std::printf(" %.1f|%.1f", sum[0] / std::max(1, count[0]), sum[1] / std::max(1, count[1]));
  }
  std::printf("\n");
  // One-ring holes where punch_holes may put them (below the cut by 8 mm, 10 mm off the ends).
  std::vector<std::vector<int>> ring(static_cast<size_t>(mesh.V.rows()));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int c = 0; c < 3; ++c)
      for (int d = 0; d < 3; ++d) ring[static_cast<size_t>(mesh.F(f, c))].push_back(mesh.F(f, d));
  double widest = 0.0;
  Eigen::Vector3d where = Eigen::Vector3d::Zero();
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    const Eigen::Vector3d p = mesh.V.row(v);
    if (!(p.z() < shape.top_cut_z_mm(p.x()) - 8.0 && p.x() > 10.0 && p.x() < params.length_mm - 10.0)) continue;
    Eigen::Vector3d low = Eigen::Vector3d::Constant(1e9), high = -low;
    for (int u : ring[static_cast<size_t>(v)]) {
      if (u == v) continue;
      low = low.cwiseMin(mesh.V.row(u).transpose());
      high = high.cwiseMax(mesh.V.row(u).transpose());
    }
    if ((high - low).norm() > widest) widest = (high - low).norm(), where = p;
  }
  std::printf("widest one-ring hole %.2f mm at (%.1f, %.1f, %.1f)\n", widest, where.x(), sign * where.y(), where.z());
  return 0;
}
