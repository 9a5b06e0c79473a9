// Nesting benchmark: every ESICUP strip instance and every Baldacci leather instance in
// /work/shared/data/nesting, each with the given time limits and thread count. Every layout is
// validated by the independent Clipper checker (engine/nest/layout_check). Prints two tables:
//   strips: utilisation, strip length, points below the best-known utilisation (sparrow's records);
//   hides:  pieces placed / demanded, hides used, utilisation of the used hides.
// Usage: nest_bench [--data DIR] [--limits 10,60] [--threads 2] [--workers 4] [--seed 1] [--only NAME[,NAME...]]
//                   [--svg-dir DIR]
//                   [--rounds N]   (N improvement rounds instead of a time limit: a deterministic run whose
//                                   wall time compares the speed of two builds)
//                   [--sweeps N]   (strips: N separation steps instead of a time limit: deterministic, and
//                                   proportional to the work, so two variants of the search compare
//                                   on equal CPU under any machine load)
//                   [--trace 1]    (every improvement on stderr: seconds since start, strip length)
//                   [--digest 1]   (below each table, a digest of every layout's placements: with --sweeps,
//                                   identical digests before and after a change = the change kept every layout)
//        nest_bench --limits 20 --svg-dir DIR --instance FILE   (options before --instance)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "engine/nest/layout_check.hpp"
#include "engine/nest/layout_svg.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/nest/nester.hpp"

namespace {

// Best-known utilisation (%) from /work/shared/data/README.md (sparrow, arXiv:2509.13329).
const std::map<std::string, double> kBestKnown = {{"albano", 89.82}, {"blaz1", 86.22}, {"dagli", 90.17},
                                                  {"fu", 92.40},     {"jakobs1", 89.25}, {"jakobs2", 87.72},
                                                  {"mao", 86.87},    {"marques", 92.02}, {"shapes0", 69.98}};

std::vector<std::filesystem::path> json_files(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  lastcut::bench::BenchOptions bench;
  bench.data = LASTCUT_SHARED_DATA_DIR "/nesting";
  int trace = 0;
  std::string instance_file;
  CLI::App app{"Nesting benchmark: the strip nester on the ESICUP instances against their best-known lengths "
               "(markdown tables, docs/benchmarks-nest.md)"};
  bench.add_options(app);
  app.add_option("--trace", trace, "1: print every improvement on stderr");
  app.add_option("--instance", instance_file, "one instance file (strip or hides): one run per limit, with its picture");
  CLI11_PARSE(app, argc, argv);
  if (!instance_file.empty()) {
    const lastcut::NestInstance instance = lastcut::read_nest_instance(instance_file);
    for (double limit : bench.limits) {
      const lastcut::NestOptions options = bench.nest_options(limit);
      const lastcut::Layout layout = lastcut::nest(instance, options);
      const auto problems = lastcut::check_layout(layout, instance);
      std::printf("%s %g s: %zu placed, %zu unplaced entries, %d hides, length %.1f, utilisation %.2f %%, %s\n", instance.name.c_str(), limit,
                  layout.placements.size(), layout.unplaced.size(), lastcut::used_bin_count(layout), layout.strip_length.value_or(0),
                  100 * layout.utilisation, problems.empty() ? "valid" : problems.front().c_str());
      if (!bench.svg_dir.empty()) lastcut::write_layout_svg(bench.svg_dir / ("nest-" + instance.name + ".svg"), layout, instance);
      if (!problems.empty()) return 1;
    }
    return 0;
  }
  auto selected = [&bench](const std::filesystem::path& file) { return bench.selected(file.stem().string()); };
  auto options_for = [&bench](double limit) { return bench.nest_options(limit); };
  int invalid = 0;
  for (double limit : bench.limits) {
    std::printf("\n## strip packing, %g s, %d threads, %d sweep workers, seed %llu\n\n", limit, bench.threads, bench.workers,
                static_cast<unsigned long long>(bench.seed));
    std::printf("| instance | pieces | utilisation %% | strip length | best-known %% | gap (points) | valid |\n|---|---|---|---|---|---|---|\n");
    double gap_sum = 0, worst_gap = 0;
    int count = 0;
    std::vector<std::string> digests;  // below the table, not inside it
    for (const auto& file : json_files(bench.data / "esicup")) {
      if (!selected(file)) continue;
      const lastcut::NestInstance instance = lastcut::read_nest_instance(file);
      lastcut::NestOptions options = options_for(limit);
      if (bench.rounds > 0) options.time_limit_s = 1e9, options.iteration_limit = bench.rounds;
      if (bench.sweeps > 0) options.time_limit_s = 1e9, options.sweep_limit = bench.sweeps;
      const auto start = std::chrono::steady_clock::now();
      if (trace)
        options.on_improvement = [&start, name = file.stem().string()](const lastcut::Layout& l) {
          std::fprintf(stderr, "%s %7.2f s  length %.3f  utilisation %.2f %%\n", name.c_str(),
                       std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                       l.strip_length.value_or(0), 100 * l.utilisation);
        };
      const lastcut::Layout layout = lastcut::nest(instance, options);
      if (bench.rounds > 0 || bench.sweeps > 0)
        std::printf("%s: %ld %s in %.2f s\n", instance.name.c_str(), bench.sweeps > 0 ? bench.sweeps : bench.rounds,
                    bench.sweeps > 0 ? "separation steps" : "rounds",
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      const auto problems = lastcut::check_layout(layout, instance);
      invalid += problems.empty() ? 0 : 1;
      if (!bench.svg_dir.empty()) lastcut::write_layout_svg(bench.svg_dir / ("nest-" + instance.name + ".svg"), layout, instance);
      const double best = kBestKnown.count(file.stem()) ? kBestKnown.at(file.stem()) : 0;
      const double gap = best - 100 * layout.utilisation;
      gap_sum += gap, worst_gap = std::max(worst_gap, gap), ++count;
      if (bench.digest) digests.push_back("digest " + instance.name + ": " + lastcut::bench::layout_digest(layout));
      std::printf("| %s | %zu | %.2f | %.3f | %.2f | %.2f | %s |\n", instance.name.c_str(), layout.placements.size(),
                  100 * layout.utilisation, layout.strip_length.value_or(0), best, gap,
                  problems.empty() ? "yes" : problems.front().c_str());
      std::fflush(stdout);
    }
    if (count) std::printf("| **average** | | | | | %.2f (worst %.2f) | |\n", gap_sum / count, worst_gap);
    if (!digests.empty()) std::printf("\n");
    for (const std::string& line : digests) std::printf("%s\n", line.c_str());
    digests.clear();

    std::printf("\n## leather hides, %g s, %d threads, seed %llu\n\n", limit, bench.threads, static_cast<unsigned long long>(bench.seed));
    std::printf("| instance | pieces placed / demanded | hides used / available | utilisation of used hides %% | valid |\n|---|---|---|---|---|\n");
    for (const auto& file : json_files(bench.data / "leather")) {
      if (!selected(file)) continue;
      const lastcut::NestInstance instance = lastcut::read_nest_instance(file);
      const lastcut::NestOptions options = options_for(limit);
      const lastcut::Layout layout = lastcut::nest(instance, options);
      const auto problems = lastcut::check_layout(layout, instance);
      invalid += problems.empty() ? 0 : 1;
      if (!bench.svg_dir.empty()) lastcut::write_layout_svg(bench.svg_dir / ("nest-" + instance.name + ".svg"), layout, instance);
      int demanded = 0, available = 0;
      for (const auto& item : instance.items) demanded += item.demand;
      for (const auto& bin : instance.bins) available += bin.stock;
      if (bench.digest) digests.push_back("digest " + instance.name + ": " + lastcut::bench::layout_digest(layout));
      std::printf("| %s | %zu / %d | %d / %d | %.2f | %s |\n", instance.name.c_str(), layout.placements.size(), demanded,
                  lastcut::used_bin_count(layout), available, 100 * layout.utilisation,
                  problems.empty() ? "yes" : problems.front().c_str());
      std::fflush(stdout);
    }
    if (!digests.empty()) std::printf("\n");
    for (const std::string& line : digests) std::printf("%s\n", line.c_str());
  }
  std::printf("\ninvalid layouts: %d\n", invalid);
  return invalid == 0 ? 0 : 1;
}
