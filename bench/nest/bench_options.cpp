#include "bench_options.hpp"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <sstream>

namespace lastcut::bench {

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream list(text);
  for (std::string part; std::getline(list, part, ',');) parts.push_back(part);
  return parts;
}

std::string layout_digest(const Layout& layout) {
  std::uint64_t hash = 14695981039346656037ull;
  const auto add = [&hash](std::uint64_t word) {
    for (int byte = 0; byte < 8; ++byte) hash = (hash ^ ((word >> (8 * byte)) & 0xff)) * 1099511628211ull;
  };
  for (const Placement& p : layout.placements) {
    add(static_cast<std::uint64_t>(p.item)), add(static_cast<std::uint64_t>(p.bin)), add(static_cast<std::uint64_t>(p.copy));
    add(p.mirrored ? 1 : 0);
    add(std::bit_cast<std::uint64_t>(p.rotation_deg)), add(std::bit_cast<std::uint64_t>(p.x)), add(std::bit_cast<std::uint64_t>(p.y));
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

void BenchOptions::add_options(CLI::App& app) {
  app.add_option("--data", data, "instance folder")->capture_default_str();
  app.add_option("--limits", limits, "time limits, s, comma-separated: one run each")->delimiter(',')->capture_default_str();
  app.add_option("--threads", threads, "threads")->capture_default_str();
  app.add_option("--workers", workers, "strips: sweeps compared per separation step")->capture_default_str();
  app.add_option("--seed", seed, "random seed")->capture_default_str();
  app.add_option("--only", only, "comma-separated instance names (default: all)");
  app.add_option("--rounds", rounds, "this many improvement rounds instead of the time limits");
  app.add_option("--sweeps", sweeps, "strips: this many separation steps instead of the time limits");
  app.add_option("--svg-dir", svg_dir, "write a picture of every layout here");
  app.add_option("--digest", digest, "1: print a digest of every layout's placements (identical digests: identical layouts)");
  app.add_option("--rotation-step", rotation_step_deg, "step of the rotations tried for freely rotating pieces, deg")
      ->capture_default_str();
}

bool BenchOptions::selected(const std::string& name) const {
  if (only.empty()) return true;
  const auto names = split_list(only);
  return std::find(names.begin(), names.end(), name) != names.end();
}

NestOptions BenchOptions::nest_options(double limit_s) {
  // Started at the first run, once --threads is known.
  if (!team_) team_ = std::make_unique<ThreadTeam>(static_cast<size_t>(std::max(0, threads - 1)));
  NestOptions options;
  options.time_limit_s = limit_s;
  options.threads = threads;
  options.sweep_workers = workers;
  options.seed = seed;
  options.free_rotation_step_deg = rotation_step_deg;
  options.run_parallel = team_->runner();
  return options;
}

}  // namespace lastcut::bench
