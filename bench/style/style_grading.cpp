// Grading a style by transfer (issue 34, "Grading on generated lasts"): style lines defined on the
// generator's own terms (planes placed in proportion to the last's length and heights) have a true place
// on every size and width; the lines of the reference size are transferred to each other last
// (engine/style/style_transfer.hpp) and every transferred point is measured against the true line there.
// The grading rule the truth follows is proportional (lengths with the length, heights with the top
// height); the generator keeps the heel pitch at 25 mm for every size, so the lasts are not scaled copies.
//   bench_style_grading                      EU 36..47 at medium width, EU 42 narrow and wide; 60k triangles
//   bench_style_grading --sizes 41 --triangles 20000   one last (the smoke test)
//   --quarter-from-ground                    the quarter line's true height graded from the ground instead
// Prints one table row per last and the mean over all: points transferred, points that ended on an edge
// of the upper, mean and worst distance to the true line (mm), the worst among the points inside the
// upper, and the seconds the transfer took (maps built once, then every line).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "engine/lastgen/generate_last.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/style_transfer.hpp"
#include "tests/support/style_line_geometry.hpp"

namespace {

namespace fs = std::filesystem;
using lastcut::test::Polyline;

struct Last {
  int eu_size;
  std::string width;  // "medium", "narrow", "wide"
};

lastcut::LastParams params_of(const Last& last, int triangles) {
  lastcut::LastParams params = lastcut::LastParams::for_eu_size(last.eu_size, lastcut::FootSide::Right);
  const double girth = last.width == "narrow" ? 0.95 : last.width == "wide" ? 1.05 : 1.0;
  params.ball_width_mm *= girth;
  params.heel_width_mm *= girth;
  params.target_triangles = triangles;
  return params;
}

// The style's lines on a last of these parameters, in the generator's frame: a vamp line across the
// instep, a quarter line around the heel (its back 45 %) and a cross line from the feather line to the top edge. The
// generator's top height is measured from the heel seat, so the quarter line is placed there too: above
// the heel seat in proportion to the top height (with quarter_from_ground: above the ground in proportion
// to it, a rule the generator's fixed 25 mm heel pitch does not follow).
std::vector<Polyline> true_lines(const lastcut::TriMesh& mesh, const lastcut::LastParams& p, bool quarter_from_ground) {
  const double length = p.length_mm, height = p.top_height_mm;
  const double quarter_z = quarter_from_ground ? 0.45 * height : p.heel_height_mm + 0.22 * height;
  const Polyline quarter_loop = lastcut::test::plane_section_through(mesh, {0, 0, 1}, {0, 0, quarter_z});
  return {lastcut::test::plane_section_through(mesh, {1, 0, 0.35}, {0.63 * length, 0, 0.36 * height}),
          lastcut::test::longest_run(quarter_loop, [&](const Eigen::Vector3d& q) { return q.x() <= 0.45 * length; }),
          lastcut::test::plane_section_through(mesh, {1, 0, 0}, {0.22 * length, 0, 0})};
}

lastcut::ScanResult segmented(const lastcut::TriMesh& mesh, const fs::path& file) {
  lastcut::write_stl_binary(file, mesh);
  lastcut::ScanOptions options;
  options.side = lastcut::FootSide::Right;
  return lastcut::scan_to_molds(file, options);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"style grading by transfer: distances of transferred style lines to their true place"};
  std::vector<int> sizes;
  int triangles = 60000, reference_size = 42;
  app.add_option("--sizes", sizes, "EU sizes to transfer to (default 36..47 and EU 42 narrow and wide)");
  app.add_option("--triangles", triangles, "triangles per last");
  app.add_option("--reference", reference_size, "EU size the style is drawn on");
  bool quarter_from_ground = false;
  app.add_flag("--quarter-from-ground", quarter_from_ground, "grade the quarter line's height from the ground");
  CLI11_PARSE(app, argc, argv);
  std::vector<Last> lasts;
  if (sizes.empty()) {
    for (int size = 36; size <= 47; ++size) lasts.push_back({size, "medium"});
    lasts.push_back({42, "narrow"});
    lasts.push_back({42, "wide"});
  } else {
    for (const int size : sizes) lasts.push_back({size, "medium"});
  }
  const fs::path scratch = fs::temp_directory_path() / ("lastcut-style-grading-" + std::to_string(::getpid()));
  fs::create_directories(scratch);

  const Last reference_last{reference_size, "medium"};
  const lastcut::LastParams reference_params = params_of(reference_last, triangles);
  const lastcut::TriMesh reference_mesh = lastcut::generate_last(reference_params).mesh;
  const lastcut::ScanResult reference = segmented(reference_mesh, scratch / "reference.stl");
  const std::vector<Polyline> style = true_lines(reference_mesh, reference_params, quarter_from_ground);

  std::printf("| EU | width | triangles | points | on an edge | mean mm | worst mm | worst inside mm | worst vamp / quarter / cross mm | transfer s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  double sum_mm = 0, worst_all_mm = 0;
  long points_all = 0;
  for (const Last& last : lasts) {
    const lastcut::LastParams params = params_of(last, triangles);
    const lastcut::TriMesh mesh = lastcut::generate_last(params).mesh;
    const lastcut::ScanResult target = segmented(mesh, scratch / "last.stl");
    const std::vector<Polyline> truth = true_lines(mesh, params, quarter_from_ground);
    const auto start = std::chrono::steady_clock::now();
    const lastcut::StyleTransfer transfer(reference, target);
    std::vector<lastcut::TransferredCurve> curves;
    for (const Polyline& line : style) curves.push_back(transfer.transfer_curve(line));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double sum = 0, worst = 0, worst_inside = 0;
    std::vector<double> worst_of_line(curves.size(), 0.0);
    int points = 0, on_edge = 0;
    for (std::size_t i = 0; i < curves.size(); ++i)
      for (const lastcut::TransferredPoint& point : curves[i].points) {
        const double off = lastcut::test::distance_to_polyline(point.position_mm, truth[i]);
        sum += off;
        worst = std::max(worst, off);
        worst_of_line[i] = std::max(worst_of_line[i], off);
        if (!point.on_outline) worst_inside = std::max(worst_inside, off);
        ++points;
        on_edge += point.on_outline ? 1 : 0;
      }
    std::printf("| %d | %s | %d | %d | %d | %.3f | %.3f | %.3f | %.2f / %.2f / %.2f | %.3f |\n", last.eu_size,
                last.width.c_str(), triangles, points, on_edge, points ? sum / points : 0.0, worst, worst_inside,
                worst_of_line[0], worst_of_line[1], worst_of_line[2], seconds);
    std::fflush(stdout);
    sum_mm += sum;
    points_all += points;
    worst_all_mm = std::max(worst_all_mm, worst);
  }
  std::printf("\n%zu lasts from EU %d: mean %.3f mm, worst %.3f mm (target: mean <= 1 mm, worst <= 3 mm)\n", lasts.size(),
              reference_size, points_all ? sum_mm / static_cast<double>(points_all) : 0.0, worst_all_mm);
  fs::remove_all(scratch);
  return 0;
}
