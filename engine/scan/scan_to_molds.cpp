#include "engine/scan/scan_to_molds.hpp"

#include <Eigen/SVD>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "engine/core/decimal_text.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/core/mesh_topology.hpp"
#include "engine/mesh/fill_holes.hpp"
#include "engine/mesh/scan_denoise.hpp"
#include "engine/mesh/sliver_collapse.hpp"
#include "engine/mold/boundary_loops.hpp"
#include "engine/orient/orient_last.hpp"

namespace lastcut {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A last may carry scan holes (segmentation closes them up to max_hole_fill_diameter_mm across); a
// larger boundary loop means the scan is an open patch or has a hole too large to close.
void refuse_open_patch(const TriMesh& mesh, const MeshTopology& topology, const SegmentOptions& options) {
  int open_loops = 0;
  double largest_mm = 0.0;
  for (const auto& loop : simple_boundary_loops(topology)) {
    const double across_mm = loop_across_mm(mesh.V, loop);
    if (across_mm <= options.max_hole_fill_diameter_mm) continue;
    ++open_loops;
    largest_mm = std::max(largest_mm, across_mm);
  }
  if (open_loops == 0) return;
  char line[240];
  std::snprintf(line, sizeof line,
                "not a closed last: %d boundary loop%s up to %.1f mm across, larger than the %.0f mm scan holes are "
                "closed up to (--max-hole); use --no-segment to flatten an open patch",
                open_loops, open_loops == 1 ? "" : "s", largest_mm, options.max_hole_fill_diameter_mm);
  throw EngineError(line);
}

void refuse_closed_patch(const MeshTopology& topology) {
  if (simple_boundary_loops(topology).empty())
    throw EngineError("the scan is a closed surface, not an open patch; drop --no-segment to cut a last into halves");
}

// A patch of a last is at most about half a metre across (check_is_last allows lasts up to 500 mm).
// Far more is a wrong length unit or a stray point far off the surface (found by fuzzing: one vertex
// moved to 161 m gave a "mold" whose spike had collapsed, area -99 %).
void refuse_absurd_patch(const TriMesh& mesh) {
  constexpr double kLargestPatch_mm = 1000.0;
  const Eigen::Vector3d extent = bounding_box_size(mesh);
  if (extent.maxCoeff() > kLargestPatch_mm) {
    char text[240];
    std::snprintf(text, sizeof text,
                  "not a patch of a last: %.0f x %.0f x %.0f mm (at most 1000 mm across; a wrong length unit, or a "
                  "stray point far off the surface?)",
                  extent.x(), extent.y(), extent.z());
    throw EngineError(text);
  }
}

// An ARAP mold keeps the surface's area within a few per cent (the FIND halves: -0.5 to -7 %). Far
// more means part of the surface collapsed or was stretched in the flattening: a spike or a fold in
// the scan. The mold is still made, with a warning for the operator to look at it.
constexpr double kAreaChangeWarning_pct = 25.0;

// Rotation (det +1) and translation that put the flattening heel left, toe right, bounding box at
// the origin (see the header).
Eigen::MatrixXd place_flattening(const Eigen::MatrixXd& UV, const std::map<std::string, int>& landmarks) {
  Eigen::Vector2d along = Eigen::Vector2d::UnitX();
  const auto heel = landmarks.find("heel");
  const auto toe = landmarks.find("toe");
  if (heel != landmarks.end() && toe != landmarks.end() && heel->second != toe->second) {
    along = (UV.row(toe->second) - UV.row(heel->second)).transpose();
  } else {
    const Eigen::RowVector2d center = UV.colwise().mean();
    const Eigen::MatrixXd centered = UV.rowwise() - center;
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(centered.transpose() * centered, Eigen::ComputeFullU);
    along = svd.matrixU().col(0);
  }
  along.normalize();
  Eigen::Matrix2d rotation;  // maps `along` to +X
  rotation << along.x(), along.y(), -along.y(), along.x();
  Eigen::MatrixXd placed = UV * rotation.transpose();
  const Eigen::RowVector2d lowest = placed.colwise().minCoeff();
  placed.rowwise() -= lowest;
  return placed;
}

// Slivers and scanner noise off the scan (engine/mesh/sliver_collapse.hpp, scan_denoise.hpp), after
// the checks that refuse absurd input (a stray point 161 m off must be refused, not smoothed).
void clean_scan(MeshIntake& intake, const DenoiseOptions& options, ScanResult& result, StageClock& clock) {
  if (const SliverReport slivers = collapse_slivers(intake.mesh); slivers.collapsed > 0) {
    intake.topology = build_mesh_topology(intake.mesh.F, intake.mesh.V.rows());
    result.notes.push_back("scan slivers: " + std::to_string(slivers.collapsed) + " edges shorter than " +
                           fixed_text(slivers.limit_mm, 2) + " mm collapsed");
    clock.lap("slivers");
  }
  const DenoiseReport denoised = denoise_scan(intake.mesh, intake.topology, options);
  if (denoised.passes > 0) {
    char note[200];
    std::snprintf(note, sizeof note, "scan noise about %.2f mm taken off (Taubin smoothing, %d passes; %.2f mm left)",
                  denoised.noise_before_mm, denoised.passes, denoised.noise_after_mm);
    result.notes.push_back(note);
  }
  clock.lap("denoise");
}

// topology: of mesh3d, built once and used by the disk check, the distortion measures and the mold.
SegmentResult flatten_segment(std::string name, TriMesh mesh3d, const MeshTopology& topology,
                              const std::map<std::string, int>& landmarks, const ScanOptions& options,
                              std::vector<std::string>& notes, StageClock& clock) {
  SegmentResult result;
  result.name = std::move(name);
  result.mesh3d = std::move(mesh3d);
  result.topology = topology;
  result.landmarks = landmarks;
  result.flatten = flatten(result.mesh3d, topology, options.flatten);
  result.UV = place_flattening(result.flatten.UV, landmarks);
  clock.lap(result.name + ": flatten");
  result.measures = measure_distortion(result.mesh3d, result.UV, topology);
  clock.lap(result.name + ": distortion");
  for (const auto& note : result.flatten.notes) notes.push_back(result.name + ": " + note);
  if (result.measures.flipped_triangles > 0)
    notes.push_back(result.name + ": " + std::to_string(result.measures.flipped_triangles) +
                    " triangles are flipped in the flattening");
  result.mold = make_mold(result.name, result.UV, result.mesh3d.F, landmarks, options.mold, topology);
  clock.lap(result.name + ": mold outline");
  result.quality = judge_half(result.name, result.mesh3d, topology, result.UV, result.measures, result.flatten.converged,
                              options.quality);
  clock.lap(result.name + ": quality gate");
  return result;
}

}  // namespace

Eigen::VectorXd triangle_strain(const DistortionMeasures& measures) {
  Eigen::VectorXd strain(measures.sigma1.size());
  for (Eigen::Index f = 0; f < strain.size(); ++f) {
    const double s2 = measures.sigma2.size() == strain.size() ? measures.sigma2(f) : 1.0;
    strain(f) = s2 > 0.0 ? std::max(measures.sigma1(f), 1.0 / s2) : std::numeric_limits<double>::infinity();
  }
  return strain;
}

ScanResult scan_to_molds(const std::filesystem::path& scan, const ScanOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  StageClock clock;
  ScanResult result;
  result.input = scan.string();
  MeshIntake intake = read_mesh(scan, options.read);
  result.intake = intake.report;
  clock.lap("read and repair");

  if (!options.segment) {
    const MeshTopology& topology = intake.topology;
    refuse_closed_patch(topology);
    refuse_absurd_patch(intake.mesh);
    clock.lap("patch check");
    if (options.denoise) clean_scan(intake, options.denoise_options, result, clock);
    result.segments.push_back(
        flatten_segment("patch", std::move(intake.mesh), topology, {}, options, result.notes, clock));
  } else {
    refuse_open_patch(intake.mesh, intake.topology, options.segment_options);
    check_is_last(intake.mesh);
    clock.lap("last check");
    if (options.denoise) clean_scan(intake, options.denoise_options, result, clock);
    const OrientedLast oriented = orient_last(intake.mesh, options.side);
    if (!oriented.side_unnamed) result.side = oriented.side;
    result.scan_to_canonical = oriented.scan_to_canonical;
    result.notes.insert(result.notes.end(), oriented.notes.begin(), oriented.notes.end());
    result.warnings = oriented.warnings;
    clock.lap("orient");
    // Orienting moves the vertices only: the intake's topology is the oriented last's.
    Segmentation halves = segment_last(oriented, intake.topology, options.segment_options);
    result.notes.insert(result.notes.end(), halves.notes.begin(), halves.notes.end());
    result.repairs = halves.repairs;
    for (const HoleRepair& repair : halves.repairs)
      if (repair.fan)
        result.warnings.push_back("a scan hole " + std::to_string(static_cast<int>(std::lround(repair.across_mm))) +
                                  " mm across is too ragged for a smooth patch: closed by a fan, check the molds there");
    clock.lap("segment");
    // Named halves come medial first; unnamed ones side_a (+Y) first.
    const std::array<Segment*, 2> order = oriented.side_unnamed ? std::array<Segment*, 2>{&halves.lateral, &halves.medial}
                                                                : std::array<Segment*, 2>{&halves.medial, &halves.lateral};
    for (Segment* half : order)
      result.segments.push_back(flatten_segment(half->name, std::move(half->mesh), half->topology, half->landmarks,
                                                options, result.notes, clock));
  }
  for (const SegmentResult& segment : result.segments) {
    const double change_pct = segment.measures.area_error_pct;
    if (!(std::abs(change_pct) <= kAreaChangeWarning_pct)) {
      char text[240];
      std::snprintf(text, sizeof text,
                    "%s: the mold's area is %.0f %% %s than the surface's: part of the surface collapsed or stretched in "
                    "the flattening (a spike or a fold in the scan?); check the mold",
                    segment.name.c_str(), std::abs(change_pct), change_pct < 0 ? "smaller" : "larger");
      result.warnings.push_back(text);
      result.notes.push_back(text);
    }
  }
  result.quality.limits = options.quality;
  for (const SegmentResult& segment : result.segments) result.quality.halves.push_back(segment.quality);
  result.profile = clock.stages();
  result.seconds_total = seconds_since(start);
  return result;
}

}  // namespace lastcut
