// The thesis's Table 1 and Table 2, repeated on lastcut's own pipeline (M. Sabaliauskas, "Computerized
// modeling technology of unique footwear surface manufacturing design", doctoral thesis, Vilnius
// University 2017, section 4: ARAP, ABF++ and LSCM on 20 half lasts, 5 pairs).
//   Table 2: D_angle and D_area (engine/flatten/distortion.hpp) and the flattening time of each method.
//   Table 1: the overlap 2C/(A+B) and the corner margins (heel, toe, both ends of the top line) of each
//            method's mold against a reference mold (engine/compare). The thesis's reference was the
//            wax-foil mold of production; no such pattern exists for a generated last, so the reference
//            here is the ARAP mold of a denser scan of the same last (4x the triangles, same shape and
//            seed): the table then measures how far each method's mold is from the best mold lastcut
//            can make of that last, not from a pattern maker's.
// Lasts: generated EU 38, 40, 42, 44, 46, left and right (5 pairs, 20 halves, as in the thesis), and the
// FIND foot template (a real scanned foot, ../shared/data/meshes) cut by lastcut's own segmentation.
// Usage: bench_thesis_tables [--pairs N] [--triangles T] [--dense-factor K] [--no-find]
// Prints markdown tables (docs/thesis-tables.md).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "engine/compare/compare_outlines.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/flatten/flatten.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/read_mesh.hpp"
#include "engine/mold/mold.hpp"
#include "engine/orient/orient_last.hpp"
#include "engine/segment/segment_last.hpp"
#include "bench/flatten/bench_halves.hpp"

namespace lastcut::bench {
namespace {

struct Settings {
  int pairs = 5;
  int triangles = 50000;  // per last; the thesis's scans had 30,000-50,000
  int dense_factor = 4;
  bool find = true;
};

struct MethodRow {
  double D_angle = 0, D_area = 0, seconds = 0;
  int flipped = 0;
  double overlap_pct = 0;
  std::vector<std::pair<std::string, double>> margins_mm;  // heel, toe, top_front, top_back
  bool compared = false;  // a reference mold existed and this method's mold was compared with it
  std::string error;  // the one-line refusal when this method's mold could not be made
};

struct HalfRows {
  std::string name;
  int triangles = 0;
  MethodRow arap, abf, lscm;
};

Mold mold_of(const Segment& half, const Eigen::MatrixXd& UV) {
  return make_mold(half.name, UV, half.mesh.F, half.landmarks, MoldOptions{}, half.topology);
}

MethodRow run_method(const Segment& half, FlattenMethod method, const std::optional<Mold>& reference) {
  MethodRow row;
  FlattenOptions options;
  options.method = method;
  try {
    const auto start = std::chrono::steady_clock::now();
    const FlattenResult flat = flatten(half.mesh, half.topology, options);
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const DistortionMeasures measures = measure_distortion(half.mesh, flat.UV, half.topology);
    row.D_angle = measures.D_angle;
    row.D_area = measures.D_area;
    row.flipped = measures.flipped_triangles;
    if (!reference) return row;
    const Mold mold = mold_of(half, flat.UV);
    CompareOptions compare;
    compare.overlap.allow_mirror = false;  // the same half of the same last
    const Comparison comparison = compare_mold(mold, *reference, compare);
    row.overlap_pct = 100.0 * comparison.alignment.overlap_fraction();
    for (const CornerMatch& corner : comparison.corners) row.margins_mm.emplace_back(corner.name, corner.margin_mm);
    row.compared = true;
  } catch (const EngineError& error) {
    row.error = error.what();
  }
  return row;
}

// The ARAP mold of the dense half, or nothing (with the reason printed) when it cannot be made.
std::optional<Mold> reference_mold(const Segment& dense_half) {
  try {
    return mold_of(dense_half, flatten(dense_half.mesh, dense_half.topology).UV);
  } catch (const EngineError& error) {
    std::printf("  (no reference mold for %s: %s)\n", dense_half.name.c_str(), error.what());
    return std::nullopt;
  }
}

void add_halves(const std::string& last_name, const Segmentation& scan, const Segmentation& dense,
                std::vector<HalfRows>& rows) {
  const Segment* scan_halves[2] = {&scan.medial, &scan.lateral};
  const Segment* dense_halves[2] = {&dense.medial, &dense.lateral};
  for (int h = 0; h < 2; ++h) {
    const std::optional<Mold> reference = reference_mold(*dense_halves[h]);
    HalfRows half;
    half.name = last_name + ", " + scan_halves[h]->name;
    half.triangles = scan_halves[h]->mesh.triangle_count();
    half.arap = run_method(*scan_halves[h], FlattenMethod::Arap, reference);
    half.abf = run_method(*scan_halves[h], FlattenMethod::Abf, reference);
    half.lscm = run_method(*scan_halves[h], FlattenMethod::Lscm, reference);
    std::fprintf(stderr, "  %s done\n", half.name.c_str());
    rows.push_back(std::move(half));
  }
}

Segmentation segment_generated(int eu_size, FootSide side, int triangles) {
  LastParams params = LastParams::for_eu_size(eu_size, side);
  // Legacy surface: the figures in docs/ were measured on it (docs/subdivision.md).
  params.surface = LastSurface::Remeshed;
  params.target_triangles = triangles;
  params.noise_mm = 0.05;
  return segment_last(orient_last(generate_last(params).mesh));
}

std::string margins_text(const MethodRow& row) {
  if (!row.error.empty()) return "refused";
  if (!row.compared) return "-";
  std::string text = "(";
  for (size_t i = 0; i < row.margins_mm.size(); ++i) {
    char number[32];
    std::snprintf(number, sizeof number, "%s%.1f", i ? ", " : "", row.margins_mm[i].second);
    text += number;
  }
  return text + ")";
}

std::string overlap_text(const MethodRow& row) {
  if (!row.error.empty()) return "refused: " + row.error;
  if (!row.compared) return "no reference";
  char text[32];
  std::snprintf(text, sizeof text, "%.2f %%", row.overlap_pct);
  return text;
}

void print_tables(const std::vector<HalfRows>& rows) {
  std::printf("\n### Table 1 repeated: overlap 2C/(A+B) and corner margins (mm) against the ARAP mold of the 4x denser scan\n\n");
  std::printf("| half | triangles | ABF++ 2C/(A+B) | ABF++ margins | LSCM 2C/(A+B) | LSCM margins | ARAP 2C/(A+B) | ARAP margins |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const HalfRows& half : rows)
    std::printf("| %s | %d | %s | %s | %s | %s | %s | %s |\n", half.name.c_str(), half.triangles,
                overlap_text(half.abf).c_str(), margins_text(half.abf).c_str(), overlap_text(half.lscm).c_str(),
                margins_text(half.lscm).c_str(), overlap_text(half.arap).c_str(), margins_text(half.arap).c_str());
  std::printf("\nMargins in the order the mold carries its corners: ");
  if (!rows.empty())
    for (const auto& [name, margin] : rows.front().arap.margins_mm) std::printf("%s ", name.c_str());
  std::printf("\n\n### Table 2 repeated: D_angle, D_area (2 is ideal) and flattening time\n\n");
  std::printf("| half | ARAP D_angle | ARAP D_area | ARAP s | ABF++ D_angle | ABF++ D_area | ABF++ s | LSCM D_angle | LSCM D_area | LSCM s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const HalfRows& half : rows)
    std::printf("| %s | %.5f | %.5f | %.3f | %.5f | %.5f | %.3f | %.5f | %.5f | %.3f |\n", half.name.c_str(),
                half.arap.D_angle, half.arap.D_area, half.arap.seconds, half.abf.D_angle, half.abf.D_area,
                half.abf.seconds, half.lscm.D_angle, half.lscm.D_area, half.lscm.seconds);

  // Averages over the halves every method could be measured on (as the thesis's last row).
  // Overlap and margins over the halves compared with a reference, the measures over every half.
  struct Sum { double overlap = 0, D_angle = 0, D_area = 0, seconds = 0; std::vector<double> margins; int count = 0, compared = 0; };
  auto add = [](Sum& sum, const MethodRow& row) {
    if (!row.error.empty()) return;
    sum.D_angle += row.D_angle;
    sum.D_area += row.D_area;
    sum.seconds += row.seconds;
    ++sum.count;
    if (!row.compared) return;
    sum.overlap += row.overlap_pct;
    sum.margins.resize(std::max(sum.margins.size(), row.margins_mm.size()), 0.0);
    for (size_t i = 0; i < row.margins_mm.size(); ++i) sum.margins[i] += row.margins_mm[i].second;
    ++sum.compared;
  };
  Sum arap, abf, lscm;
  for (const HalfRows& half : rows) {
    add(arap, half.arap);
    add(abf, half.abf);
    add(lscm, half.lscm);
  }
  std::printf("\n### Averages (overlap and margins over the halves compared with a reference mold)\n\n");
  std::printf("| method | halves | compared | 2C/(A+B) | margins (mean, mm) | D_angle | D_area | seconds |\n|---|---|---|---|---|---|---|---|\n");
  const std::pair<const char*, const Sum*> methods[] = {{"ABF++", &abf}, {"LSCM", &lscm}, {"ARAP", &arap}};
  for (const auto& [name, sum] : methods) {
    if (sum->count == 0) {
      std::printf("| %s | 0 | 0 | - | - | - | - | - |\n", name);
      continue;
    }
    std::string margins = "(";
    for (size_t i = 0; i < sum->margins.size(); ++i) {
      char number[32];
      std::snprintf(number, sizeof number, "%s%.1f", i ? ", " : "", sum->margins[i] / std::max(sum->compared, 1));
      margins += number;
    }
    margins += ")";
    std::printf("| %s | %d | %d | %.2f %% | %s | %.5f | %.5f | %.3f |\n", name, sum->count, sum->compared,
                sum->overlap / std::max(sum->compared, 1), margins.c_str(), sum->D_angle / sum->count, sum->D_area / sum->count, sum->seconds / sum->count);
  }
}

}  // namespace
}  // namespace lastcut::bench

int main(int argc, char** argv) {
  using namespace lastcut;
  using namespace lastcut::bench;
  Settings settings;
  bool no_find = false;
  CLI::App app{"The thesis's Table 1 (overlap, corner margins) and Table 2 (D_angle, D_area, time) repeated for ARAP, "
               "ABF++ and LSCM on lastcut's own pipeline (markdown tables, docs/thesis-tables.md)"};
  app.add_option("--pairs", settings.pairs, "pairs of generated lasts, EU 38, 40, .. 46 left and right (at most 5 are run)")
      ->capture_default_str();
  app.add_option("--triangles", settings.triangles, "triangles per last")
      ->capture_default_str()
      ->check(CLI::Range(1, std::numeric_limits<int>::max()));
  app.add_option("--dense-factor", settings.dense_factor, "the reference scan has this many times the triangles")
      ->capture_default_str()
      ->check(CLI::Range(1, std::numeric_limits<int>::max()));
  app.add_flag("--no-find", no_find, "leave out the FIND foot");
  CLI11_PARSE(app, argc, argv);
  settings.find = !no_find;
  std::printf("Lasts of %d triangles, reference molds from scans of %d triangles (ARAP).\n", settings.triangles,
              settings.triangles * settings.dense_factor);
  std::vector<HalfRows> rows;
  const int sizes[] = {38, 40, 42, 44, 46};
  for (int pair = 0; pair < settings.pairs && pair < 5; ++pair) {
    for (FootSide side : {FootSide::Left, FootSide::Right}) {
      const std::string name = "EU " + std::to_string(sizes[pair]) + " " + std::string(to_string(side));
      try {
        add_halves(name, segment_generated(sizes[pair], side, settings.triangles),
                   segment_generated(sizes[pair], side, settings.triangles * settings.dense_factor), rows);
      } catch (const EngineError& error) {
        std::printf("  (%s not segmented: %s)\n", name.c_str(), error.what());
      }
    }
  }
  if (settings.find) {
    try {
      add_halves("FIND foot", find_foot_segmentation(settings.triangles),
                 find_foot_segmentation(settings.triangles * settings.dense_factor), rows);
    } catch (const EngineError& error) {
      std::printf("  (FIND foot not segmented: %s)\n", error.what());
    }
  }
  print_tables(rows);
  return 0;
}
