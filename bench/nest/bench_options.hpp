#pragma once
// The options nest_bench and hide_bench share (--data --limits --threads --workers --seed --only
// --rounds --sweeps --svg-dir --digest) and the NestOptions they make, with one ThreadTeam (daemon/cli/thread_team.hpp)
// started once for all runs: a sweep's tasks do not start threads.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "daemon/cli/thread_team.hpp"
#include "engine/nest/layout.hpp"
#include "engine/nest/nest_options.hpp"

namespace lastcut::bench {

struct BenchOptions {
  std::filesystem::path data;           // instance folder
  std::vector<double> limits = {10, 60};  // time limits, s: one run each
  int threads = 2;
  int workers = NestOptions{}.sweep_workers;  // strips: sweeps compared per separation step
  std::uint64_t seed = 1;
  std::string only;                     // comma-separated instance names; empty: all
  long rounds = 0;                      // > 0: this many improvement rounds instead of the time limits
  long sweeps = 0;                      // > 0 (strips): this many separation steps instead of the time limits
  std::filesystem::path svg_dir;        // when set: a picture of every layout
  int digest = 0;                       // 1: a digest of every layout's placements (a refactor must keep them)
  double rotation_step_deg = NestOptions{}.free_rotation_step_deg;  // poses of freely rotating pieces

  // Registers the shared options on the benchmark's command line (CLI11: --help, unknown options refused).
  void add_options(CLI::App& app);
  // --only lets the instance named `name` run.
  bool selected(const std::string& name) const;
  // NestOptions for one run with time limit limit_s on the team's threads (--rounds and --sweeps are
  // the caller's: nest_bench bounds only its strip runs by them).
  NestOptions nest_options(double limit_s);

 private:
  std::unique_ptr<ThreadTeam> team_;
};

// FNV-1a (64 bit, hex) over every placement's item, hide, copy, mirror flag and the exact bits of its
// rotation and position: two layouts with the same digest place every piece identically, so a
// refactor that must not change results is checked exactly, not by the summary figures.
std::string layout_digest(const Layout& layout);

// "a,b,c" -> {"a", "b", "c"}.
std::vector<std::string> split_list(const std::string& text);

}  // namespace lastcut::bench
