// Yield benchmark (issue 35): pairs of the shipped styles (config/styles/derby and loafer) on sizes over
// EU 36-47, cut from generated lasts through the real pipeline (style_pairs.hpp: one scanned last per
// pair, the other foot mirrored), nested on the hides of one Baldacci et al. (2014) leather instance
// scaled to mm (baldacci_hides.hpp: a backbone along each outline's principal axis, the file's holes
// and quality zones) through the daemon's batch entry (hide_batch + nest_batch: each pair one pair
// group, so on one hide). The hide search and the greedy run on the same instance at the same time
// limit; every layout goes through the independent checker (layout_check). The time to make the
// pieces is printed on its own and is not in the nest times. Figures: docs/benchmarks-nest.md.
//   piece_yield_bench                                  20 pairs (derby, loafer in turn), Test3's hides, 60 s, 2 threads
//   piece_yield_bench --pairs 1 --time-limit 5 --threads 1    the smoke test
//   piece_yield_bench --relax pairs                    a diagnostic: the same without one rule (grain, grade, pairs)
//   piece_yield_bench --side-by-side                   a pair's pieces next to each other (BatchSpec::side_by_side), not
//                                                      anywhere on their hide: the rule before issue 35 changed it
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "baldacci_hides.hpp"
#include "daemon/cli/thread_team.hpp"
#include "engine/nest/hide_batch.hpp"
#include "engine/nest/layout_svg.hpp"
#include "style_pairs.hpp"
#include "yield_figures.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Arguments {
  double time_limit_s = 60;
  int threads = 2;
  std::uint64_t seed = 1;
  int pairs = 20;
  std::vector<int> sizes;  // empty: spread over EU 36..47
  std::vector<std::string> styles = {"derby", "loafer"};
  fs::path hides = fs::path(LASTCUT_SHARED_DATA_DIR) / "nesting" / "leather" / "baldacci3.json";
  double mm_per_unit = 0.15;
  double gap_mm = 2, margin_mm = 5;
  int triangles = 20000;
  std::vector<std::string> methods = {"search", "greedy"};
  fs::path svg_dir;
  std::vector<std::string> relax;  // diagnostics: rules dropped to measure what each costs
  bool side_by_side = false;       // BatchSpec::side_by_side
  bool no_mirror = false;          // !BatchSpec::mirror_pairs
};

// Drops the named rules from the instance (after hide_batch made it): grain (free rotation), grade (any
// leather), pairs (each piece on any hide). Not the instance: a diagnostic of what holds the yield back.
void relax_rules(lastcut::BatchInstance& batch, const std::vector<std::string>& relax) {
  const auto dropped = [&](const char* rule) { return std::find(relax.begin(), relax.end(), rule) != relax.end(); };
  for (lastcut::NestItem& item : batch.instance.items) {
    if (dropped("grain")) item.grain_deg.reset(), item.grain_tolerance_deg = 0;
    if (dropped("grade")) item.min_quality = 0, item.quality_regions.clear();
    if (dropped("pairs")) item.pair_group = "piece " + std::to_string(item.id);
  }
}

std::string grain_text(const std::map<double, double>& worst) {
  std::string text;
  char part[48];
  for (const auto& [tolerance, deviation] : worst) {
    std::snprintf(part, sizeof part, "%s%.1f (%g)", text.empty() ? "" : ", ", deviation, tolerance);
    text += part;
  }
  return text.empty() ? "-" : text;
}

void print_instance(const Arguments& args, const std::vector<lastcut::bench::PairOrder>& orders,
                    const lastcut::BatchInstance& batch, double pieces_s) {
  std::map<std::string, int> per_style;
  int smallest = 99, largest = 0;
  for (const auto& order : orders) {
    ++per_style[order.style];
    smallest = std::min(smallest, order.eu_size), largest = std::max(largest, order.eu_size);
  }
  std::string styles;
  for (const auto& [style, count] : per_style) styles += (styles.empty() ? "" : ", ") + style + " " + std::to_string(count);
  const lastcut::bench::AreaBound bound = lastcut::bench::area_bound(batch.instance);
  double usable = 0, least = 1e300, most = 0;
  for (const lastcut::Bin& hide : batch.instance.bins) {
    const double a = lastcut::bench::usable_area_mm2(hide);
    usable += a, least = std::min(least, a), most = std::max(most, a);
  }
  std::printf("pieces: %zu pairs (%s), EU %d-%d, %zu pieces of %.3f m^2; made in %.1f s (not in the nest times)\n",
              orders.size(), styles.c_str(), smallest, largest, batch.instance.items.size(), bound.pieces_mm2 * 1e-6, pieces_s);
  std::printf("hides: %s, %zu hides at %g mm per unit, usable %.2f-%.2f m^2 (%.2f m^2 in all), backbone along each "
              "outline's principal axis; gap %g mm, margin %g mm\n",
              args.hides.filename().c_str(), batch.instance.bins.size(), args.mm_per_unit, least * 1e-6, most * 1e-6,
              usable * 1e-6, args.gap_mm, args.margin_mm);
  std::string backbones;  // where the grain runs on each hide: the principal axis, not a measured backbone
  char angle[16];
  for (const lastcut::Bin& hide : batch.instance.bins) {
    std::snprintf(angle, sizeof angle, "%s%.1f", backbones.empty() ? "" : ", ", hide.backbone_deg.value_or(0.0));
    backbones += angle;
  }
  std::printf("backbones, deg from the hides' x axis: %s\n", backbones.c_str());
  std::printf("area bound: %d hides (largest first); utilisation at most %.2f %% (the pieces over the least usable "
              "area of any hides that cover them)\n",
              bound.fewest_hides, 100 * bound.best_utilisation);
}

}  // namespace

int main(int argc, char** argv) {
  Arguments args;
  CLI::App app{"Yield benchmark (issue 35): pairs of the shipped styles on Baldacci hides, the hide search against the "
               "greedy (a markdown table, docs/benchmarks-nest.md)"};
  app.add_option("--time-limit", args.time_limit_s, "seconds per nest (each method)")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--threads", args.threads, "threads of the nester")->check(CLI::Range(1, 64))->capture_default_str();
  app.add_option("--seed", args.seed, "random seed of the nester")->capture_default_str();
  app.add_option("--pairs", args.pairs, "pairs of shoes (the styles in turn)")->check(CLI::Range(1, 200))->capture_default_str();
  app.add_option("--sizes", args.sizes, "EU sizes in turn, comma-separated (default: spread over 36..47)")
      ->delimiter(',')->check(CLI::Range(35, 47));
  app.add_option("--styles", args.styles, "styles in turn, comma-separated (folders of config/styles)")
      ->delimiter(',')->check(CLI::IsMember({"derby", "loafer"}))->capture_default_str();
  app.add_option("--hides", args.hides, "a Baldacci leather instance (jagua-rs JSON): its hides are the leather")
      ->check(CLI::ExistingFile)->capture_default_str();
  app.add_option("--mm-per-unit", args.mm_per_unit, "scale of the Baldacci hides (0.15: calf skins of 1.1-1.6 m^2)")
      ->check(CLI::Range(0.05, 0.4))->capture_default_str();
  app.add_option("--gap", args.gap_mm, "gap between pieces, mm")->check(CLI::Range(0.0, 20.0))->capture_default_str();
  app.add_option("--margin", args.margin_mm, "margin to the hide's edge and holes, mm")->check(CLI::Range(0.0, 50.0))->capture_default_str();
  app.add_option("--triangles", args.triangles, "triangles of each generated last")->check(CLI::Range(5000, 200000))->capture_default_str();
  app.add_option("--methods", args.methods, "search, greedy (comma-separated)")
      ->delimiter(',')->check(CLI::IsMember({"search", "greedy"}))->capture_default_str();
  app.add_option("--svg-dir", args.svg_dir, "write a picture of each layout here");
  app.add_option("--relax", args.relax, "diagnostics, comma-separated: drop rules (grain, grade, pairs) to measure their cost")
      ->delimiter(',')->check(CLI::IsMember({"grain", "grade", "pairs"}));
  app.add_flag("--side-by-side", args.side_by_side, "a pair's pieces next to each other on their hide (the rule before issue 35)");
  app.add_flag("--no-mirror", args.no_mirror, "leave a pair's pieces where the nester put them (no mirroring about the backbone)");
  CLI11_PARSE(app, argc, argv);

  try {
    const auto orders = lastcut::bench::spread_pairs(args.pairs, args.sizes, args.styles);
    const auto pieces_start = Clock::now();
    std::vector<lastcut::PieceGroup> groups;
    {
      lastcut::bench::PairMaker maker(fs::path(LASTCUT_SOURCE_DIR) / "config" / "styles", args.triangles);
      for (std::size_t k = 0; k < orders.size(); ++k) groups.push_back(maker.make(orders[k], static_cast<int>(k)));
    }
    const double pieces_s = seconds_since(pieces_start);

    lastcut::BatchSpec spec;
    spec.pairs = lastcut::PairPolicy::SameHide;
    spec.gap_mm = args.gap_mm;
    spec.margin_mm = args.margin_mm;
    spec.side_by_side = args.side_by_side;
    spec.mirror_pairs = !args.no_mirror;
    // The pieces carry their own grain and grade (the style's); the batch adds no rule of its own.
    const auto hides = lastcut::bench::baldacci_hides(args.hides, args.mm_per_unit);
    lastcut::BatchInstance batch = lastcut::hide_batch(groups, hides, spec, "piece-yield");
    relax_rules(batch, args.relax);
    print_instance(args, orders, batch, pieces_s);
    for (const std::string& rule : args.relax) std::printf("RELAXED (a diagnostic, not the issue's rules): %s\n", rule.c_str());
    if (args.side_by_side) std::printf("pairs side by side (--side-by-side: the rule before issue 35)\n");

    std::printf("\n## %zu pairs on %s, %g s, %d threads, seed %llu\n\n", orders.size(), args.hides.filename().c_str(),
                args.time_limit_s, args.threads, static_cast<unsigned long long>(args.seed));
    std::printf("| method | placed / pieces | hides used | utilisation of used hides %% | least filled hide %% | "
                "worst grain deg (tolerance) | pairs on one hide | pieces mirrored about the backbone | checker | nest s |\n"
                "|---|---|---|---|---|---|---|---|---|---|\n");
    std::fflush(stdout);
    lastcut::ThreadTeam team(static_cast<std::size_t>(args.threads - 1));
    std::vector<std::string> fills;  // below the table
    int invalid = 0;
    for (const std::string& method : args.methods) {
      lastcut::NestOptions options;
      options.time_limit_s = args.time_limit_s;
      options.threads = args.threads;
      options.seed = args.seed;
      options.run_parallel = team.runner();
      options.hide_method = method == "greedy" ? lastcut::HideMethod::Greedy : lastcut::HideMethod::Search;
      const auto start = Clock::now();
      const lastcut::Layout layout = lastcut::nest_batch(batch, options);
      const double nest_s = seconds_since(start);
      const lastcut::bench::YieldFigures figures = lastcut::bench::measure_yield(batch, layout);
      invalid += figures.problems.empty() ? 0 : 1;
      std::printf("| %s | %d / %d | %zu | %.2f | %.2f | %s | %d / %d | %d / %d | %s | %.1f |\n", method.c_str(),
                  figures.placed, figures.demanded, figures.hides.size(), 100 * figures.utilisation,
                  100 * figures.least_hide_utilisation, grain_text(figures.worst_grain_deg).c_str(),
                  figures.pairs_on_one_hide, figures.pairs, figures.twins.mirrored, figures.twins.pairs,
                  figures.problems.empty() ? "valid" : figures.problems.front().c_str(), nest_s);
      std::fflush(stdout);
      std::string line = method + " fills %:";
      char part[96];
      for (const auto& fill : figures.hides) {
        std::snprintf(part, sizeof part, " %s %.1f (%.2f m^2);", fill.hide.c_str(), 100 * fill.placed_mm2 / fill.usable_mm2,
                      fill.usable_mm2 * 1e-6);
        line += part;
      }
      fills.push_back(line);
      if (!args.svg_dir.empty())
        lastcut::write_layout_svg(args.svg_dir / ("piece-yield-" + method + ".svg"), layout, batch.instance);
    }
    std::printf("\n");
    for (const std::string& line : fills) std::printf("%s\n", line.c_str());
    std::printf("invalid layouts: %d\n", invalid);
    return invalid == 0 ? 0 : 1;
  } catch (const std::exception& error) {  // EngineError among them: one line either way
    std::fprintf(stderr, "piece_yield_bench: %s\n", error.what());
    return 1;
  }
}
