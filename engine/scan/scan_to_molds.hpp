#pragma once
// The scan-to-molds pipeline, as the command line (`lastcut flatten`) and the daemon run it:
//   read the scan (units, repair, refusal of bad input)       engine/mesh/read_mesh.hpp
//   stand it in the canonical frame, tell left from right     engine/orient/orient_last.hpp
//   cut it into medial and lateral halves (thesis 3.1)        engine/segment/segment_last.hpp
//   flatten each half with ARAP, LSCM or ABF++ (thesis 2.2-2.4) engine/flatten/flatten.hpp
//   measure the distortion, make the mold outline and notches engine/flatten/distortion.hpp, engine/mold
// A scan hole up to segment_options.max_hole_fill_diameter_mm across is closed (engine/mesh/fill_holes.hpp);
// a larger one is refused. A symmetric last with no side named gives halves side_a and side_b.
// With segment = false the scan must already be one disk-shaped patch; it is flattened as it is
// and named "patch". A closed last without segmentation, or an open patch with it, is refused.
//
// Each flattening is turned rigidly (never mirrored) so that its mold lies heel left, toe right
// (heel -> toe landmark along +X) with its bounding box starting at (0, 0); a patch without
// landmarks is turned so its longest extent is along X. Rigid motions do not change any measure.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/foot_side.hpp"
#include "engine/core/stage_clock.hpp"
#include "engine/core/tri_mesh.hpp"
#include "engine/flatten/flatten.hpp"
#include "engine/mesh/read_mesh.hpp"
#include "engine/mesh/scan_denoise.hpp"
#include "engine/mold/mold.hpp"
#include "engine/scan/mold_quality_gate.hpp"
#include "engine/segment/segment_last.hpp"

namespace lastcut {

struct ScanOptions {
  MeshReadOptions read;
  bool segment = true;  // false: the scan is one open patch, flattened as it is
  FlattenOptions flatten;
  MoldOptions mold;
  SegmentOptions segment_options;
  MoldQualityLimits quality;      // the gate each half is judged by (mold_quality_gate.hpp)
  bool denoise = true;            // take scanner noise off first, where the scan has it (engine/mesh/scan_denoise.hpp)
  DenoiseOptions denoise_options; // when the scan has noise, and how much smoothing
  std::optional<FootSide> side;  // the foot as the operator names it (--side, the sidecar): settles a
                                 // symmetric last; a clearly other-footed scan keeps its own side and warns
};

struct SegmentResult {
  std::string name;             // "medial", "lateral" or "patch"; "side_a", "side_b" for an unnamed symmetric last
  TriMesh mesh3d;               // the triangles that were flattened, mm (canonical frame when segmented)
  MeshTopology topology;        // of mesh3d
  std::map<std::string, int> landmarks;  // boundary vertices "toe", "heel", "top_front", "top_back" (none for a patch)
  Eigen::MatrixXd UV;           // #V x 2, mm, same vertex order as mesh3d, placed as described above
  FlattenResult flatten;        // iterations, timings, notes (its UV is the unplaced one)
  DistortionMeasures measures;  // of UV against mesh3d
  Mold mold;                    // outline and notches in the UV coordinates
  HalfVerdict quality;          // the gate's judgement of UV (mold_quality_gate.hpp)
};

struct ScanResult {
  std::string input;                 // the scan's path as given
  IntakeReport intake;               // what reading the file found and repaired
  std::optional<FootSide> side;      // known when segmented, unless a symmetric last with no side named
  Eigen::Affine3d scan_to_canonical = Eigen::Affine3d::Identity();  // rigid: the scan's frame to the segments' (after cleaning)
  std::vector<SegmentResult> segments;
  std::vector<std::string> notes;    // from orientation, segmentation and flattening, one line each
  std::vector<std::string> warnings; // what the operator should look at (also among the notes)
  std::vector<HoleRepair> repairs;   // scan holes closed before segmentation
  MoldQuality quality;               // every segment's gate verdict, in segment order
  double seconds_total = 0;
  std::vector<StageTime> profile;    // wall seconds per stage ("read", "medial: flatten", ...), in order
};

// Throws EngineError with one line an operator can act on.
ScanResult scan_to_molds(const std::filesystem::path& scan, const ScanOptions& options);

// The larger of sigma1 and 1/sigma2 per triangle (#F): how much the leather is stretched or
// compressed there, as a factor >= 1 (infinite for a flipped triangle).
Eigen::VectorXd triangle_strain(const DistortionMeasures& measures);

}  // namespace lastcut
