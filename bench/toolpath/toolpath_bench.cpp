// bench_toolpath: for every ESICUP strip-packing instance (/work/shared/data/nesting/esicup),
// nest it with lastcut's nester (short time limit) or read a saved layout, then plan the cut
// program twice: pieces in the layout's own order and in our order (nearest neighbour + 2-opt +
// Or-opt), and print tool-up travel of both, their ratio, and the time to plan and write HPGL
// and G-code. Usage: bench_toolpath [--time-limit S] [--layouts DIR] [--save DIR] [--repeat N]
#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "engine/core/engine_error.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/toolpath/cut_file.hpp"
#include "engine/toolpath/layout_pieces.hpp"
#include "engine/toolpath/plan_cut_program.hpp"
#include "engine/nest/nester.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  }
  return "unknown CPU";
}


double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  double time_limit_s = 2.0;
  int repeat = 5;
  std::filesystem::path layouts_dir, save_dir;
  CLI::App app{"Cutting-order benchmark: tool-up travel of our piece order vs the layout's own order on the ESICUP "
               "instances, and the time to plan and write HPGL and G-code"};
  app.add_option("--time-limit", time_limit_s, "nester time limit per instance (s)")->capture_default_str();
  app.add_option("--layouts", layouts_dir, "read saved layouts <instance>.json from this folder instead of nesting");
  app.add_option("--save", save_dir, "write each instance's layout into this folder as <instance>.json");
  app.add_option("--repeat", repeat, "plan and write each program N times, report the medians (below 1: once)")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  repeat = std::max(1, repeat);
  const std::filesystem::path esicup = std::filesystem::path(LASTCUT_SHARED_DATA_DIR) / "nesting" / "esicup";
  std::vector<std::filesystem::path> instances;
  for (const auto& entry : std::filesystem::directory_iterator(esicup)) {
    if (entry.path().extension() == ".json") instances.push_back(entry.path());
  }
  std::sort(instances.begin(), instances.end());

  lastcut::MachineProfile profile =
      lastcut::load_machine_profile("hpgl-knife-cutter", lastcut::standard_machine_profile_dirs());
  std::printf("machine: %s, %u hardware threads; profile hpgl-knife-cutter (drag knife 0.3 mm, pen labels)\n",
              cpu_model().c_str(), std::thread::hardware_concurrency());
  const std::string made_by = "lastcut's nester, time limit " + std::to_string(time_limit_s) + " s";
  std::printf("layouts: %s\n\n", layouts_dir.empty() ? made_by.c_str() : layouts_dir.c_str());
  std::printf("| instance | pieces | travel, layout order (mm) | travel, nearest neighbour (mm) | travel, ours (mm) | ratio ours/layout | ratio ours/NN | cut length (mm) | plan (ms) | HPGL (ms) | G-code (ms) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  double ratio_product = 1.0;
  int count = 0;
  for (const auto& path : instances) {
    const std::string name = path.stem().string();
    try {
      lastcut::NestInstance instance;
      lastcut::Layout layout;
      if (!layouts_dir.empty()) {
        const lastcut::LayoutFile file = lastcut::read_layout_file(layouts_dir / (name + ".json"));
        instance = file.instance;
        layout = file.layout;
      } else {
        instance = lastcut::read_nest_instance(path);
        lastcut::NestOptions options;
        options.time_limit_s = time_limit_s;
        layout = lastcut::nest(instance, options);
      }
      if (!save_dir.empty()) {
        std::filesystem::create_directories(save_dir);
        lastcut::write_layout(save_dir / (name + ".json"), layout, instance);
      }
      const auto pieces = lastcut::placed_pieces(layout, instance, lastcut::SheetRef{});
      // The bench machine's table is the strip (ESICUP units are taken as mm).
      double max_x = 0, max_y = 0;
      for (const auto& piece : pieces) {
        for (const auto& point : piece.outline.points) {
          max_x = std::max(max_x, point.x());
          max_y = std::max(max_y, point.y());
        }
      }
      profile.work_area_x_mm = max_x + 1.0;
      profile.work_area_y_mm = max_y + 1.0;
      const lastcut::CutStats given =
          lastcut::measure_program(lastcut::plan_cut_program(pieces, profile, lastcut::PieceOrder::AsGiven));
      const lastcut::CutStats nearest = lastcut::measure_program(
          lastcut::plan_cut_program(pieces, profile, lastcut::PieceOrder::NearestNeighbour));
      std::vector<double> plan_ms, hpgl_ms, gcode_ms;
      lastcut::CutStats ours;
      size_t bytes = 0;
      for (int r = 0; r < repeat; ++r) {
        auto start = Clock::now();
        const lastcut::CutProgram program = lastcut::plan_cut_program(pieces, profile);
        plan_ms.push_back(milliseconds_since(start));
        start = Clock::now();
        bytes += lastcut::write_cut_file(program, profile, lastcut::CutFileFormat::Hpgl).size();
        hpgl_ms.push_back(milliseconds_since(start));
        start = Clock::now();
        bytes += lastcut::write_cut_file(program, profile, lastcut::CutFileFormat::Gcode).size();
        gcode_ms.push_back(milliseconds_since(start));
        ours = lastcut::measure_program(program);
      }
      const double ratio = ours.travel_length_mm / given.travel_length_mm;
      ratio_product *= ratio;
      ++count;
      std::printf("| %s | %zu | %.0f | %.0f | %.0f | %.3f | %.3f | %.0f | %.1f | %.1f | %.1f |\n", name.c_str(),
                  pieces.size(), given.travel_length_mm, nearest.travel_length_mm, ours.travel_length_mm, ratio,
                  ours.travel_length_mm / nearest.travel_length_mm, ours.cut_length_mm, median(plan_ms),
                  median(hpgl_ms), median(gcode_ms));
      if (bytes == 0) return 1;
    } catch (const lastcut::EngineError& error) {
      std::printf("| %s | failed: %s |\n", name.c_str(), error.what());
    }
  }
  if (count > 0) std::printf("\ngeometric mean of the travel ratio (ours / layout order): %.3f over %d instances\n",
                             std::pow(ratio_product, 1.0 / count), count);
  return 0;
}
