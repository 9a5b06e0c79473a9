// The cost of a style's pieces beyond `lastcut flatten` (issue 34, "Speed": <= 1.0 s on one core for
// a 100k-triangle last): a derby drawn on a reference last (tests/support/derby_style.hpp) is taken to a
// new last, split into its pieces, each piece cut from the surface, flattened and grown by its
// allowances. Both lasts go through scan_to_molds first (that is `lastcut flatten`, not counted).
//   bench_style_pieces                 reference and new last 100k triangles, 5 runs
//   bench_style_pieces --triangles 20000 --runs 1   (the smoke test)
// Prints the stages of the best run (seconds) and min/median/max of the total over the runs.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "engine/lastgen/generate_last.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/piece_mold.hpp"
#include "engine/style/piece_surface.hpp"
#include "engine/style/style_transfer.hpp"
#include "engine/style/upper_regions.hpp"
#include "tests/support/derby_style.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

lastcut::ScanResult segmented(const lastcut::TriMesh& mesh, const fs::path& file) {
  lastcut::write_stl_binary(file, mesh);
  lastcut::ScanOptions options;
  options.side = lastcut::FootSide::Right;
  return lastcut::scan_to_molds(file, options);
}

double since(Clock::time_point& mark) {
  const auto now = Clock::now();
  const double seconds = std::chrono::duration<double>(now - mark).count();
  mark = now;
  return seconds;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"the cost of a style's pieces beyond lastcut flatten"};
  int triangles = 100000, runs = 5;
  app.add_option("--triangles", triangles, "triangles of both lasts");
  app.add_option("--runs", runs, "repetitions (the best one's stages are printed)");
  CLI11_PARSE(app, argc, argv);
  const fs::path scratch = fs::temp_directory_path() / ("lastcut-style-pieces-" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  lastcut::LastParams params = lastcut::LastParams::for_eu_size(42, lastcut::FootSide::Right);
  params.target_triangles = triangles;
  const lastcut::TriMesh reference_mesh = lastcut::generate_last(params).mesh;
  const lastcut::ScanResult reference = segmented(reference_mesh, scratch / "reference.stl");
  params.random_pose = true;
  params.seed = 5;
  params.ball_width_mm *= 1.04;  // another last: a little wider, remeshed, posed
  const lastcut::ScanResult target = segmented(lastcut::generate_last(params).mesh, scratch / "new.stl");
  const std::array<const lastcut::SegmentResult*, 2> halves = {&target.segments[0], &target.segments[1]};

  std::vector<double> totals;
  std::vector<std::pair<std::string, double>> best_stages;
  std::vector<std::string> piece_lines;
  for (int run = 0; run < runs; ++run) {
    std::vector<std::pair<std::string, double>> stages;
    std::vector<std::string> lines_of_run;
    const auto start = Clock::now();
    auto mark = start;
    const lastcut::StyleTransfer transfer(reference, target);
    stages.emplace_back("forme maps and locators", since(mark));
    const lastcut::test::TransferredDerby derby = lastcut::test::transfer_derby(reference_mesh, transfer);
    stages.emplace_back("lines and labels transferred", since(mark));
    const std::vector<lastcut::PieceRegion> regions = lastcut::piece_regions(halves, derby.lines, derby.labels, derby.cuts);
    const lastcut::PieceEdgeCurves curves = lastcut::piece_edge_curves(halves, derby.lines, target.scan_to_canonical);
    stages.emplace_back("piece regions", since(mark));
    double cutting = 0, molds = 0;
    for (const lastcut::PieceRegion& region : regions) {
      const lastcut::PieceSurface piece = lastcut::cut_piece_surface(halves, region);
      cutting += since(mark);
      const lastcut::PieceMold mold = lastcut::make_piece_mold(
          piece, curves, [&](const lastcut::PieceEdgeSource& source) { return lastcut::test::derby_allowance(piece.name, source); });
      molds += since(mark);
      char text[200];
      std::snprintf(text, sizeof text, "| %s | %ld | %d | %.4f | %.4f | %d | %d |", piece.name.c_str(),
                    static_cast<long>(piece.mesh.F.rows()), mold.flatten.iterations, mold.measures.D_angle, mold.measures.D_area,
                    mold.measures.flipped_triangles, static_cast<int>(mold.edges.size()));
      lines_of_run.push_back(text);
    }
    stages.emplace_back("pieces cut from the surface", cutting);
    stages.emplace_back("pieces flattened, outlines grown", molds);
    totals.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    if (totals.back() <= *std::min_element(totals.begin(), totals.end())) best_stages = stages, piece_lines = lines_of_run;
  }
  std::printf("| piece | triangles | ARAP iterations | D_angle | D_area | flipped | edges |\n|---|---|---|---|---|---|---|\n");
  for (const std::string& line : piece_lines) std::printf("%s\n", line.c_str());
  std::printf("\n| stage (best run) | s |\n|---|---|\n");
  for (const auto& [stage, seconds] : best_stages) std::printf("| %s | %.3f |\n", stage.c_str(), seconds);
  std::sort(totals.begin(), totals.end());
  std::printf("\nstyle pieces beyond lastcut flatten, %d triangles, %d runs: min %.3f s, median %.3f s, max %.3f s\n", triangles,
              runs, totals.front(), totals[totals.size() / 2], totals.back());
  fs::remove_all(scratch);
  return 0;
}
