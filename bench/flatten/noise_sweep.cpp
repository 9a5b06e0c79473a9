// Noise sweep (issue 36): generated lasts as scanners deliver them, through the whole scan-to-molds
// pipeline with its quality gate, each case judged against the noise-free mold of the same last.
// A case ends one of three ways:
//   held   the quality gate (engine/scan/mold_quality_gate.hpp) or the intake refused it: never cut;
//   good   molds passed the gate and are right: D_angle and D_area <= 2.02, no flipped triangle,
//          outline within 1 mm (symmetric Hausdorff) of the noise-free mold after rigid alignment;
//   WRONG  molds passed the gate but are not right: the failure the gate exists to prevent.
// Cases: EU sizes x surfaces (remeshed: even triangles; lofted: rings and pole slivers, as scanner
// exports mesh) x triangle counts x noise 0..0.3 mm (along normals / isotropic) x holes, random
// poses. Prints one row per case and the totals; figures and the command: docs/benchmarks-noise.md.
//   bench_noise_sweep [--quick] [--strict] [--surface lofted] [--triangles N] [--size EU] [--seams N] [--smooth-all]
//                     [--truth same|fine]
//   --strict: exit 1 when any case is WRONG; --surface/--triangles/--size: only those cases;
//   --seams N: N stitching seams in every scan, judged against the seamless noise-free mold;
//   --smooth-all: smooth every scan, the noise-free reference too (tells smoothing's own effect apart)
//   --truth fine: judge against the same last remeshed at 150,000 triangles without noise
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <chrono>
#include <optional>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/mold/outline_alignment.hpp"
#include "engine/scan/scan_to_molds.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

struct Case {
  int eu_size = 41;
  LastSurface surface = LastSurface::Remeshed;
  int triangles = 20000;
  double noise_mm = 0;
  ScanNoise kind = ScanNoise::AlongNormal;
  int holes = 0;
  uint64_t seed = 1;
  int seams = 0;
};

struct Outcome {
  std::string verdict;  // held, good, WRONG
  std::string detail;   // the reason held, or the worst measure of a good / wrong case
  double worst_outline_mm = 0;
  double seconds = 0;
};

const char* surface_name(LastSurface surface) { return surface == LastSurface::Lofted ? "lofted" : "remeshed"; }

struct Sweep {
  bool quick = false, strict = false, smooth_all = false;
  std::string surface;  // empty: both
  int triangles = 0;    // 0: both counts
  int eu_size = 0;      // 0: three sizes
  int seams = 0;        // stitching seams in every scan but the noise-free reference
  // The reference: "same" (default), the noise-free scan of the same last and triangulation; "fine", the
  // noise-free scan of the same last remeshed at 150,000 triangles, the nearest the sweep has to the
  // last's exact surface (a coarse lofted mesh is itself a faceted copy of it).
  std::string truth = "same";
};

ScanResult run_case(const Case& c, bool pose, bool smooth_all, const fs::path& scratch) {
  LastParams params = LastParams::for_eu_size(c.eu_size, FootSide::Right);
  params.surface = c.surface;
  params.target_triangles = c.triangles;
  params.noise_mm = c.noise_mm;
  params.noise_kind = c.kind;
  params.holes = c.holes;
  params.seams = c.seams;
  params.random_pose = pose;
  params.seed = c.seed;
  const fs::path scan = scratch / "scan.stl";
  write_stl_binary(scan, generate_last(params).mesh);
  ScanOptions options;
  options.side = FootSide::Right;
  if (smooth_all) options.denoise_options.min_noise_mm = -1.0;
  return scan_to_molds(scan, options);
}

Outcome judge(const Case& c, const ScanResult* reference, bool smooth_all, const fs::path& scratch) {
  Outcome outcome;
  const auto start = std::chrono::steady_clock::now();
  try {
    const ScanResult result = run_case(c, true, smooth_all, scratch);
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!result.quality.passed()) {
      outcome.verdict = "held";
      outcome.detail = result.quality.reason();
      return outcome;
    }
    std::string wrong;
    for (const SegmentResult& segment : result.segments) {
      const DistortionMeasures& m = segment.measures;
      if (!(m.D_angle <= 2.02 && m.D_area <= 2.02)) wrong += segment.name + " D above 2.02; ";
      if (m.flipped_triangles > 0) wrong += segment.name + " flipped; ";
      if (!reference) continue;
      for (const SegmentResult& truth : reference->segments) {
        if (truth.name != segment.name) continue;
        const double off_mm = hausdorff_distance_mm(transformed(segment.mold.outline, align_molds(segment.mold, truth.mold)),
                                                    truth.mold.outline, 0.5);
        outcome.worst_outline_mm = std::max(outcome.worst_outline_mm, off_mm);
        if (off_mm > 1.0) wrong += segment.name + " outline " + std::to_string(off_mm).substr(0, 5) + " mm off; ";
      }
    }
    outcome.verdict = wrong.empty() ? "good" : "WRONG";
    outcome.detail = wrong;
  } catch (const EngineError& error) {
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    outcome.verdict = "held";
    outcome.detail = std::string("refused: ") + error.what();
  }
  return outcome;
}

int run(const Sweep& sweep) {
  const bool quick = sweep.quick;
  const fs::path scratch = fs::temp_directory_path() / ("lastcut-noise-sweep-" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  std::vector<int> sizes = quick ? std::vector<int>{41} : std::vector<int>{36, 41, 47};
  if (sweep.eu_size) sizes = {sweep.eu_size};
  std::vector<LastSurface> surfaces = {LastSurface::Remeshed, LastSurface::Lofted};
  if (!sweep.surface.empty()) surfaces = {sweep.surface == "lofted" ? LastSurface::Lofted : LastSurface::Remeshed};
  std::vector<int> counts = quick ? std::vector<int>{20000} : std::vector<int>{20000, 150000};
  if (sweep.triangles) counts = {sweep.triangles};
  const std::vector<double> noises = quick ? std::vector<double>{0.2} : std::vector<double>{0.0, 0.1, 0.2, 0.3};
  const std::vector<int> hole_counts = quick ? std::vector<int>{0} : std::vector<int>{0, 3};
  int cases = 0, held = 0, good = 0, wrong = 0, low_noise = 0, low_noise_molds = 0;
  std::printf("| EU | surface | triangles | noise mm | kind | holes | verdict | outline mm | s | why |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const int size : sizes)
    for (const LastSurface surface : surfaces)
      for (const int triangles : counts) {
        Case base{size, surface, triangles, 0.0, ScanNoise::AlongNormal, 0, static_cast<uint64_t>(size)};
        Case truth = base;
        if (sweep.truth == "fine") {
          truth.surface = LastSurface::Remeshed;
          truth.triangles = 150000;
        }
        std::optional<ScanResult> reference;
        try {
          reference = run_case(truth, false, sweep.smooth_all, scratch);
        } catch (const EngineError&) {
          reference.reset();  // no noise-free mold: the outline test is skipped, the rest still applies
        }
        for (const double noise : noises)
          for (const ScanNoise kind : {ScanNoise::AlongNormal, ScanNoise::Isotropic}) {
            if (noise == 0.0 && kind == ScanNoise::Isotropic) continue;
            for (const int holes : hole_counts) {
              Case c = base;
              c.noise_mm = noise;
              c.kind = kind;
              c.holes = holes;
              c.seams = sweep.seams;
              c.seed = base.seed * 131 + static_cast<uint64_t>(noise * 100) + static_cast<uint64_t>(holes) * 7;
              const Outcome outcome = judge(c, reference ? &*reference : nullptr, sweep.smooth_all, scratch);
              ++cases;
              held += outcome.verdict == "held";
              good += outcome.verdict == "good";
              wrong += outcome.verdict == "WRONG";
              if (noise <= 0.2) {
                ++low_noise;
                low_noise_molds += outcome.verdict != "held";
              }
              std::printf("| %d | %s | %d | %.1f | %s | %d | %s | %.2f | %.1f | %s |\n", size, surface_name(surface),
                          triangles, noise, kind == ScanNoise::Isotropic ? "isotropic" : "normal", holes,
                          outcome.verdict.c_str(), outcome.worst_outline_mm, outcome.seconds,
                          outcome.detail.substr(0, 160).c_str());
              std::fflush(stdout);
            }
          }
      }
  fs::remove_all(scratch);
  std::printf("\ncases %d: good %d, held %d, WRONG %d (done with a wrong mold)\n", cases, good, held, wrong);
  std::printf("noise <= 0.2 mm: %d of %d cases give molds (%.0f %%)\n", low_noise_molds, low_noise,
              low_noise ? 100.0 * low_noise_molds / low_noise : 0.0);
  return sweep.strict && wrong > 0 ? 1 : 0;
}

}  // namespace
}  // namespace lastcut

int main(int argc, char** argv) {
  CLI::App app{"noise sweep: the scan pipeline and its quality gate on generated scans (docs/benchmarks-noise.md)"};
  lastcut::Sweep sweep;
  app.add_flag("--quick", sweep.quick, "one last, one noise level (the smoke test)");
  app.add_flag("--strict", sweep.strict, "exit 1 when any case is done with a wrong mold");
  app.add_option("--surface", sweep.surface, "only this triangulation")->check(CLI::IsMember({"remeshed", "lofted"}));
  app.add_option("--triangles", sweep.triangles, "only this triangle count");
  app.add_option("--size", sweep.eu_size, "only this EU size");
  app.add_option("--seams", sweep.seams, "stitching seams (0.2 mm step) in every scan but the seamless, noise-free reference");
  app.add_flag("--smooth-all", sweep.smooth_all, "smooth every scan, the noise-free reference too");
  app.add_option("--truth", sweep.truth, "the reference: the same triangulation without noise, or the same last remeshed fine")
      ->check(CLI::IsMember({"same", "fine"}));
  CLI11_PARSE(app, argc, argv);
  return lastcut::run(sweep);
}
