#include "bench_options.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace lastcut::bench {

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream list(text);
  for (std::string part; std::getline(list, part, ',');) parts.push_back(part);
  return parts;
}

bool BenchOptions::parse(const std::string& key, const std::string& value) {
  if (key == "--data") data = value;
  else if (key == "--threads") threads = std::atoi(value.c_str());
  else if (key == "--workers") workers = std::atoi(value.c_str());
  else if (key == "--seed") seed = std::strtoull(value.c_str(), nullptr, 10);
  else if (key == "--only") only = value;
  else if (key == "--rounds") rounds = std::atol(value.c_str());
  else if (key == "--sweeps") sweeps = std::atol(value.c_str());
  else if (key == "--svg-dir") svg_dir = value;
  else if (key == "--limits") {
    limits.clear();
    for (const std::string& item : split_list(value)) limits.push_back(std::atof(item.c_str()));
  } else {
    return false;
  }
  return true;
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
  options.run_parallel = team_->runner();
  return options;
}

}  // namespace lastcut::bench
