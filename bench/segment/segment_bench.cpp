// Orientation and segmentation speed on generated last scans (0.2 mm noise, 3 holes, random pose),
// and with --sweep a correctness table over every EU size 35-47, both sides.
// Prints tables; the figures go into docs/benchmarks-segment.md. Single thread, as the engine is.
//   segment_bench            speed at 25k, 50k and 100k triangles (median of 7 runs)
//   segment_bench --sweep    EU 35..47 x left/right at 20k triangles
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <numbers>
#include <vector>

#include <CLI/CLI.hpp>

#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/orient/orient_last.hpp"
#include "engine/segment/segment_last.hpp"

namespace {

using Clock = std::chrono::steady_clock;

lastcut::GeneratedLast scan_of(int eu_size, lastcut::FootSide side, int triangles, std::uint64_t seed) {
  lastcut::LastParams params = lastcut::LastParams::for_eu_size(eu_size, side);
  // Legacy surface: the figures in docs/ were measured on it (docs/subdivision.md).
  params.surface = lastcut::LastSurface::Remeshed;
  params.target_triangles = triangles;
  params.noise_mm = 0.2;
  params.holes = 3;
  params.random_pose = true;
  params.seed = seed;
  return lastcut::generate_last(params);
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

template <typename Work>
double seconds_of(Work&& work) {
  const auto start = Clock::now();
  work();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// CPU time of this thread: what one core spends, whatever else the machine runs meanwhile.
double thread_cpu_s() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

void speed_table() {
  std::printf("| triangles | orient_last median s | segment_last median s | total median s | total min s | total CPU median s |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|\n");
  for (int triangles : {25000, 50000, 100000}) {
    const lastcut::GeneratedLast scan = scan_of(42, lastcut::FootSide::Left, triangles, 7);
    std::vector<double> orient_s, segment_s, total_s, cpu_s;
    for (int run = 0; run < 7; ++run) {
      lastcut::OrientedLast last;
      const double cpu_start = thread_cpu_s();
      orient_s.push_back(seconds_of([&] { last = lastcut::orient_last(scan.mesh); }));
      segment_s.push_back(seconds_of([&] { (void)lastcut::segment_last(last); }));
      cpu_s.push_back(thread_cpu_s() - cpu_start);
      total_s.push_back(orient_s.back() + segment_s.back());
    }
    std::printf("| %d | %.3f | %.3f | %.3f | %.3f | %.3f |\n", static_cast<int>(scan.mesh.F.rows()), median(orient_s),
                median(segment_s), median(total_s), *std::min_element(total_s.begin(), total_s.end()), median(cpu_s));
    std::fflush(stdout);
  }
}

void sweep_table() {
  std::printf("| EU | side | detected | rotation error deg | medial/lateral area | halves are disks | segment s |\n");
  std::printf("|---:|---|---|---:|---:|---|---:|\n");
  int failures = 0;
  for (int size = 35; size <= 47; ++size)
    for (lastcut::FootSide side : {lastcut::FootSide::Left, lastcut::FootSide::Right}) {
      const lastcut::GeneratedLast scan = scan_of(size, side, 20000, 100 + static_cast<std::uint64_t>(size));
      try {
        const lastcut::OrientedLast last = lastcut::orient_last(scan.mesh);
        const Eigen::Matrix3d truth = scan.canonical_to_scan.linear().transpose();
        const double error_deg =
            Eigen::AngleAxisd(last.scan_to_canonical.linear() * truth.transpose()).angle() * 180.0 / std::numbers::pi;
        lastcut::Segmentation result;
        const double segment_s = seconds_of([&] { result = lastcut::segment_last(last); });
        const double ratio = lastcut::surface_area(result.medial.mesh) / lastcut::surface_area(result.lateral.mesh);
        if (last.side != side) ++failures;
        std::printf("| %d | %s | %s | %.2f | %.3f | yes | %.3f |\n", size, std::string(to_string(side)).c_str(),
                    std::string(to_string(last.side)).c_str(), error_deg, ratio, segment_s);
      } catch (const lastcut::EngineError& error) {
        ++failures;
        std::printf("| %d | %s | FAILED: %s | | | | |\n", size, std::string(to_string(side)).c_str(), error.what());
      }
      std::fflush(stdout);
    }
  std::printf("\n%d failures\n", failures);
}

}  // namespace

int main(int argc, char** argv) {
  bool sweep = false;
  CLI::App app{"Orientation and segmentation speed on generated last scans (0.2 mm noise, 3 holes, random pose); "
               "with --sweep a correctness table over EU 35-47, both sides"};
  app.add_flag("--sweep", sweep,
               "the correctness table over EU 35..47 x left/right at 20k triangles instead of the speed table");
  CLI11_PARSE(app, argc, argv);
  if (sweep)
    sweep_table();
  else
    speed_table();
  return 0;
}
