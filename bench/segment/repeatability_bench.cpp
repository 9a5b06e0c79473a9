// Repeatability of the molds: pairs of scans of one last that differ as two real scans
// do (another pose, 0.2 mm scanner noise with another seed, another triangle density, 3 holes)
// go through the whole scan-to-molds pipeline; the molds of each half are aligned rigidly and
// their outlines compared by the symmetric Hausdorff distance. Prints a table per pair and half,
// with where on the first mold the largest gap lies (mm from its bounding-box corner), so a change
// to the segmentation can be measured over many pairs, not one lucky one. Also printed: the 3D
// areas and boundary lengths of both halves, the flattening's boundary error, the largest gap
// between the two cut curves in 3D (canonical frames; it includes the small difference between
// the two orientations, so it is a where-to-look, not a measure), and any segmentation note that
// the normal angle had to be used.
//   repeatability_bench            12 pairs: EU 36..46, both feet, 16k vs 24k triangles
//   repeatability_bench --quick    the 3 pairs the scan test checks
//   --no-noise, --no-pose, --same-density, --no-holes  drop one difference between the scans,
//   to see which one moves the molds
//   --feather-height MM, --rim-depth MM  segmentation options (engine/segment/segment_last.hpp)
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mold/outline_alignment.hpp"
#include "engine/scan/scan_to_molds.hpp"

namespace {

namespace fs = std::filesystem;

struct Pair {
  int eu_size;
  lastcut::FootSide side;
  std::uint64_t seed;
};

fs::path write_scan(const fs::path& dir, const std::string& name, const lastcut::LastParams& params) {
  const fs::path path = dir / (name + ".stl");
  lastcut::write_stl_binary(path, lastcut::generate_last(params).mesh);
  return path;
}

const lastcut::SegmentResult& named(const lastcut::ScanResult& result, const std::string& name) {
  for (const auto& segment : result.segments)
    if (segment.name == name) return segment;
  throw lastcut::EngineError("no segment " + name);
}

struct Farthest {
  lastcut::Point2 point = lastcut::Point2::Zero();
  double distance_mm = -1.0;
};

// The point of `a` farthest from outline `b` (the one-sided part of the Hausdorff distance).
Farthest farthest_point(const lastcut::Polygon2& a, const lastcut::Polygon2& b) {
  const std::vector<lastcut::Point2> samples = lastcut::sample_outline(a, 0.25);
  const std::vector<lastcut::Point2> targets = lastcut::sample_outline(b, 0.25);
  Farthest worst;
  for (const auto& p : samples) {
    double nearest = 1e300;
    for (const auto& q : targets) nearest = std::min(nearest, (p - q).norm());
    if (nearest > worst.distance_mm) worst = {p, nearest};
  }
  return worst;
}

// Boundary edges (used by one triangle) of a mesh as 3D segments, mm.
std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> boundary_segments(const lastcut::TriMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments;
  for (const auto& [edge, count] : uses)
    if (count == 1) segments.emplace_back(mesh.V.row(edge.first).transpose(), mesh.V.row(edge.second).transpose());
  return segments;
}

// One-sided Hausdorff distance (mm) from the boundary of a to the boundary of b, in 3D: how far
// apart the cut curves of two segmentations lie on the surface, before any flattening.
std::pair<double, Eigen::Vector3d> boundary_gap_3d_mm(const lastcut::TriMesh& a, const lastcut::TriMesh& b) {
  const auto from = boundary_segments(a), to = boundary_segments(b);
  double worst = 0.0;
  Eigen::Vector3d where = Eigen::Vector3d::Zero();
  for (const auto& [p, q] : from)
    for (double t : {0.0, 0.5}) {
      const Eigen::Vector3d x = p + t * (q - p);
      double nearest = 1e300;
      for (const auto& [u, w] : to) {
        const Eigen::Vector3d d = w - u;
        const double s = std::clamp((x - u).dot(d) / std::max(d.squaredNorm(), 1e-12), 0.0, 1.0);
        nearest = std::min(nearest, (u + s * d - x).squaredNorm());
      }
      if (nearest > worst) { worst = nearest; where = x; }
    }
  return {std::sqrt(worst), where};
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, no_noise = false, no_pose = false, same_density = false, no_holes = false;
  lastcut::ScanOptions options;
  CLI::App app{"Repeatability of the molds: pairs of scans of one last that differ as two real scans do go through "
               "scan-to-molds; the molds of each half are aligned and compared by the Hausdorff distance"};
  app.add_flag("--quick", quick, "only the 3 pairs the scan test checks (default: 12 pairs, EU 36..46, both feet)");
  app.add_flag("--no-noise", no_noise, "no 0.2 mm scanner noise on the scans");
  app.add_flag("--no-pose", no_pose, "no random pose: both scans in the canonical frame");
  app.add_flag("--same-density", same_density, "both scans at 16k triangles (default: 16k vs 24k)");
  app.add_flag("--no-holes", no_holes, "no holes in the scans (default: 3)");
  app.add_option("--feather-height", options.segment_options.feather_height_mm,
                 "segmentation: feather line height above the fitted sole surface (mm)")
      ->capture_default_str();
  app.add_option("--rim-depth", options.segment_options.rim_depth_mm,
                 "segmentation: top rim depth below the fitted top plane (mm)")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  const bool noise = !no_noise, pose = !no_pose, density = !same_density, holes = !no_holes;
  std::vector<Pair> pairs;
  if (quick) {
    pairs = {{42, lastcut::FootSide::Left, 11}, {38, lastcut::FootSide::Right, 21}, {45, lastcut::FootSide::Left, 31}};
  } else {
    int size = 36;
    for (std::uint64_t seed = 11; seed < 23; ++seed, size = size >= 46 ? 36 : size + 1)
      pairs.push_back({size, seed % 2 ? lastcut::FootSide::Left : lastcut::FootSide::Right, seed * 10});
  }
  const fs::path dir = fs::temp_directory_path() / ("lastcut-repeatability-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::printf(
      "| EU | side | seeds | half | Hausdorff mm | worst at x mm | worst at y mm | area 3D cm^2 a/b | boundary 3D mm a/b | "
      "boundary 2D/3D %% a/b | 3D cut gap mm |\n|---:|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  double worst_mm = 0.0, sum_mm = 0.0;
  int count = 0, failures = 0;
  for (const Pair& pair : pairs) {
    lastcut::LastParams first = lastcut::LastParams::for_eu_size(pair.eu_size, pair.side);
    first.surface = lastcut::LastSurface::Remeshed;  // the figures in docs/ were measured on it
    first.noise_mm = noise ? 0.2 : 0.0;
    first.random_pose = pose;
    first.holes = holes ? 3 : 0;
    first.target_triangles = 16000;
    first.seed = pair.seed;
    lastcut::LastParams second = first;
    second.target_triangles = density ? 24000 : 16000;
    second.seed = pair.seed + 1;
    try {
      const lastcut::ScanResult a = lastcut::scan_to_molds(write_scan(dir, "a", first), options);
      const lastcut::ScanResult b = lastcut::scan_to_molds(write_scan(dir, "b", second), options);
      for (const auto* result : {&a, &b})
        for (const std::string& note : result->notes)
          if (note.find("normal angle") != std::string::npos) std::printf("note: %s\n", note.c_str());
      for (const std::string name : {"medial", "lateral"}) {
        const lastcut::Mold& mold_a = named(a, name).mold;
        const lastcut::Mold& mold_b = named(b, name).mold;
        const lastcut::Polygon2 moved = lastcut::transformed(mold_b.outline, lastcut::align_molds(mold_b, mold_a));
        const double distance_mm = lastcut::hausdorff_distance_mm(moved, mold_a.outline);
        const Farthest from_a = farthest_point(mold_a.outline, moved), from_b = farthest_point(moved, mold_a.outline);
        const lastcut::Point2 at = from_a.distance_mm >= from_b.distance_mm ? from_a.point : from_b.point;
        const lastcut::DistortionMeasures& ma = named(a, name).measures;
        const lastcut::DistortionMeasures& mb = named(b, name).measures;
        auto gap = boundary_gap_3d_mm(named(a, name).mesh3d, named(b, name).mesh3d);
        const auto back = boundary_gap_3d_mm(named(b, name).mesh3d, named(a, name).mesh3d);
        if (back.first > gap.first) gap = back;
        std::printf("| %d | %s | %llu/%llu | %s | %.2f | %.0f | %.0f | %.1f/%.1f | %.1f/%.1f | %+.2f/%+.2f | %.2f at (%.0f, %.0f, %.0f) |\n", pair.eu_size,
                    pair.side == lastcut::FootSide::Left ? "left" : "right", static_cast<unsigned long long>(first.seed),
                    static_cast<unsigned long long>(second.seed), name.c_str(), distance_mm, at.x(), at.y(),
                    ma.area_3d_mm2 / 100.0, mb.area_3d_mm2 / 100.0, ma.boundary_3d_mm, mb.boundary_3d_mm,
                    ma.boundary_error_pct, mb.boundary_error_pct,
                    gap.first, gap.second.x(), gap.second.y(), gap.second.z());
        worst_mm = std::max(worst_mm, distance_mm);
        sum_mm += distance_mm;
        ++count;
      }
    } catch (const lastcut::EngineError& error) {
      std::printf("| %d | %s | %llu | failed: %s | | | |\n", pair.eu_size, pair.side == lastcut::FootSide::Left ? "left" : "right",
                  static_cast<unsigned long long>(pair.seed), error.what());
      ++failures;
    }
    std::fflush(stdout);
  }
  fs::remove_all(dir);
  std::printf("\n%d halves: mean %.2f mm, max %.2f mm, %d pair(s) failed\n", count, count ? sum_mm / count : 0.0, worst_mm,
              failures);
  return failures == 0 ? 0 : 1;
}
