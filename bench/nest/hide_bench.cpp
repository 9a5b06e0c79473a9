// Hide nesting benchmark: the six Baldacci leather instances (/work/shared/data/nesting/leather) and
// shoe-mold batches on generated calf hides, each nested by the hide search (the default) and by the
// old greedy + iterated greedy in the same run at the same limits. Every layout is validated by the
// independent Clipper checker (engine/nest/layout_check). Per instance: pieces placed / demanded,
// hides used, the area lower bound (the fewest hides, largest usable area first, whose usable area
// covers the pieces' area), utilisation of the used hides' usable area (outline minus holes).
// Usage: hide_bench [--data DIR] [--limits 10,60] [--threads 2] [--workers 4] [--seed 1]
//                   [--only NAME[,NAME...]] [--methods search,greedy] [--rounds N] [--svg-dir DIR] [--trace 1] [--digest 1]
//   --trace 1: every improvement on stderr (seconds since start, hides used, utilisation) and, per
//              final layout, each used hide's fill and what the least-filled one would need (by area)
//   --rounds N: N improvement rounds instead of the time limits (a fixed budget: compares two versions on the same work)
//   --digest 1: after each table, a digest of every layout's placements (with --rounds: identical digests
//               before and after a change = the change kept every layout)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "engine/nest/layout_check.hpp"
#include "engine/nest/layout_svg.hpp"
#include "engine/nest/mold_items.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/nest/nester.hpp"
#include "generated_hides.hpp"

namespace {

// The fewest hides, largest usable area (outline minus holes) first, whose area covers the pieces'.
int area_bound(const lastcut::NestInstance& instance) {
  double pieces = 0;
  for (const auto& item : instance.items) pieces += item.demand * std::abs(lastcut::signed_area(item.shape));
  std::vector<double> areas;
  for (const auto& bin : instance.bins) {
    double a = std::abs(lastcut::signed_area(bin.outer));
    for (const auto& hole : bin.holes) a -= std::abs(lastcut::signed_area(hole));
    for (int c = 0; c < bin.stock; ++c) areas.push_back(a);
  }
  std::sort(areas.rbegin(), areas.rend());
  double covered = 0;
  for (size_t k = 0; k < areas.size(); ++k)
    if ((covered += areas[k]) >= pieces) return static_cast<int>(k + 1);
  return static_cast<int>(areas.size()) + 1;  // not even all hides together
}

// The fill of each used hide (placed over usable area, the hide's id), least filled first, and the fill
// the others would reach by area if that hide's pieces went onto them: the room an emptying move has.
void print_fills(const lastcut::NestInstance& instance, const lastcut::Layout& layout) {
  std::vector<std::pair<double, double>> hides;  // (placed, usable) per used hide
  std::vector<int> ids;
  for (const auto& bin : instance.bins) {
    double placed = 0;
    bool used = false;
    for (const auto& p : layout.placements)
      if (p.bin == bin.id) used = true, placed += std::abs(lastcut::signed_area(lastcut::find_item(instance, p.item).shape));
    if (!used) continue;
    double usable = std::abs(lastcut::signed_area(bin.outer));
    for (const auto& hole : bin.holes) usable -= std::abs(lastcut::signed_area(hole));
    hides.emplace_back(placed, usable), ids.push_back(bin.id);
  }
  std::vector<size_t> order(hides.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return hides[a].first / hides[a].second < hides[b].first / hides[b].second; });
  double placed = 0, usable = 0;
  for (const auto& h : hides) placed += h.first, usable += h.second;
  std::fprintf(stderr, "%s fills %%:", instance.name.c_str());
  for (size_t k : order) std::fprintf(stderr, " %d:%.1f", ids[k], 100 * hides[k].first / hides[k].second);
  if (!order.empty())
    std::fprintf(stderr, "; without hide %d the others at %.1f %%\n", ids[order[0]], 100 * placed / (usable - hides[order[0]].second));
}

}  // namespace

int main(int argc, char** argv) {
  lastcut::bench::BenchOptions bench;
  bench.data = LASTCUT_SHARED_DATA_DIR "/nesting/leather";
  std::vector<std::string> methods = {"search", "greedy"};
  int trace = 0;  // 1: every improvement with its time, on stderr
  CLI::App app{"Hide nesting benchmark: the hide search against the greedy on the Baldacci leather instances and "
               "generated shoe-mold batches (markdown tables, docs/benchmarks-nest.md)"};
  bench.add_options(app);
  app.add_option("--methods", methods, "search, greedy (comma-separated)")->delimiter(',')->capture_default_str();
  app.add_option("--trace", trace, "1: print every improvement and the hides' fills on stderr");
  CLI11_PARSE(app, argc, argv);
  const std::filesystem::path& data = bench.data;
  std::vector<double>& limits = bench.limits;
  const int threads = bench.threads, workers = bench.workers;
  const std::uint64_t seed = bench.seed;
  const long rounds = bench.rounds;
  const std::filesystem::path& svg_dir = bench.svg_dir;
  std::vector<lastcut::NestInstance> instances;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(data))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const auto& file : files) instances.push_back(lastcut::read_nest_instance(file));
  for (int batch = 0; batch < 2; ++batch) instances.push_back(lastcut::bench::shoe_batch(batch));
  auto selected = [&](const lastcut::NestInstance& instance) { return bench.selected(instance.name); };
  int invalid = 0;
  if (rounds > 0) limits = {0};
  for (double limit : limits) {
    if (rounds > 0) std::printf("\n## hides, %ld rounds, %d threads, %d sweep workers, seed %llu\n\n", rounds, threads, workers, static_cast<unsigned long long>(seed));
    else std::printf("\n## hides, %g s, %d threads, %d sweep workers, seed %llu\n\n", limit, threads, workers, static_cast<unsigned long long>(seed));
    std::printf("| instance | method | placed / demanded | hides used | area bound | utilisation of used hides %% | seconds | valid |\n|---|---|---|---|---|---|---|---|\n");
    std::vector<int> hides_sum(methods.size(), 0);
    std::vector<double> utilisation_sum(methods.size(), 0);
    int bound_sum = 0, count = 0;
    std::vector<std::string> digests;  // below the table, not inside it
    for (const auto& instance : instances) {
      if (!selected(instance)) continue;
      int demanded = 0;
      for (const auto& item : instance.items) demanded += item.demand;
      const int bound = area_bound(instance);
      bound_sum += bound, ++count;
      for (size_t m = 0; m < methods.size(); ++m) {
        lastcut::NestOptions options = bench.nest_options(limit);
        if (rounds > 0) options.time_limit_s = 1e9, options.iteration_limit = rounds;
        options.hide_method = methods[m] == "greedy" ? lastcut::HideMethod::Greedy : lastcut::HideMethod::Search;
        const auto start = std::chrono::steady_clock::now();
        if (trace)
          options.on_improvement = [&](const lastcut::Layout& better) {
            std::fprintf(stderr, "%s %s %.1f s: %zu placed, %d hides, %.2f %%\n", instance.name.c_str(), methods[m].c_str(),
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                         better.placements.size(), lastcut::used_bin_count(better), 100 * better.utilisation);
          };
        const lastcut::Layout layout = lastcut::nest(instance, options);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const auto problems = lastcut::check_layout(layout, instance);
        invalid += problems.empty() ? 0 : 1;
        if (trace) print_fills(instance, layout);
        hides_sum[m] += lastcut::used_bin_count(layout);
        utilisation_sum[m] += layout.utilisation;
        if (!svg_dir.empty())
          lastcut::write_layout_svg(svg_dir / ("hides-" + instance.name + "-" + methods[m] + ".svg"), layout, instance);
        if (bench.digest) digests.push_back("digest " + instance.name + " " + methods[m] + ": " + lastcut::bench::layout_digest(layout));
        std::printf("| %s | %s | %zu / %d | %d | %d | %.2f | %.1f | %s |\n", instance.name.c_str(), methods[m].c_str(),
                    layout.placements.size(), demanded, lastcut::used_bin_count(layout), bound, 100 * layout.utilisation, seconds,
                    problems.empty() ? "yes" : problems.front().c_str());
        std::fflush(stdout);
      }
    }
    for (size_t m = 0; m < methods.size(); ++m)
      std::printf("| **all** | %s | | %d | %d | %.2f (mean) | | |\n", methods[m].c_str(), hides_sum[m], bound_sum,
                  count ? 100 * utilisation_sum[m] / count : 0.0);
    if (!digests.empty()) std::printf("\n");
    for (const std::string& line : digests) std::printf("%s\n", line.c_str());
  }
  std::printf("\ninvalid layouts: %d\n", invalid);
  return invalid == 0 ? 0 : 1;
}
