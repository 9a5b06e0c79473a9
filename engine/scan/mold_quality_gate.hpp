#pragma once
// The quality gate: is a half's mold the last's surface, or something to hold for a person?
// A mold is cut into leather unattended, so a flattening that went wrong (an outline that crossed
// itself, a fallback that stopped early, a mold stretched by scanner noise) must never pass as
// done. Each half is judged on
//   - the thesis's distortion measures D_angle and D_area (eq. 1, 2; 2 is ideal), the largest
//     and the 95th-percentile stretch (sigma1), flipped triangles and ARAP's convergence, and
//   - its length against the last's: the two outline points farthest apart in the mold are
//     joined on the 3D half by the shortest path along its edges (Dijkstra). A flattening keeps
//     lengths, so the mold's straight span cannot be much longer than that path (which is itself
//     a few percent longer than the geodesic); a crossed or torn outline makes it 10-30 % longer.
// Limits come from the configuration ([quality], docs/quality-gate.md); the defaults let every
// good scan in the test data pass (docs/benchmarks-noise.md).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"
#include "engine/flatten/distortion.hpp"
#include "engine/scan/mold_quality_limits.hpp"

namespace lastcut {

// The mold's span (mm) and the path along the 3D surface between the same two points (mm).
struct MoldSpan {
  double span_2d_mm = 0;       // the largest distance between two outline vertices of UV
  double along_surface_mm = 0; // shortest edge path between them on mesh3d
  double excess_pct() const { return along_surface_mm > 0 ? 100.0 * (span_2d_mm / along_surface_mm - 1.0) : 0.0; }
};

// mesh3d: #V x 3 mm, a disk; topology: of mesh3d; UV: #V x 2 mm, same vertex order. Throws
// EngineError when the mesh has no boundary or the two span points are not connected.
MoldSpan measure_mold_span(const TriMesh& mesh3d, const MeshTopology& topology, const Eigen::MatrixXd& UV);

struct HalfVerdict {
  std::string name;                    // "medial", "lateral", "patch"
  MoldSpan span;
  std::vector<std::string> breaches;   // one phrase per limit crossed: "D_angle 3.31 > 2.02"
};

struct MoldQuality {
  MoldQualityLimits limits;            // what the halves were judged by
  std::vector<HalfVerdict> halves;
  bool passed() const;
  // "" when passed; otherwise one line for the log and the job report:
  // "mold quality: medial D_angle 3.31 > 2.02, not converged; lateral ..."
  std::string reason() const;
  // {"passed", "reason", "limits": {...}, "halves": [{"name", "span_2d_mm", "along_surface_mm",
  //  "excess_pct", "breaches": [...]}]}
  nlohmann::json to_json() const;
};

// Judges one flattened half: mesh3d #V x 3 mm (a disk) and its topology, UV #V x 2 mm in the same
// vertex order, measures of UV against mesh3d, converged as the flattening reported it.
HalfVerdict judge_half(const std::string& name, const TriMesh& mesh3d, const MeshTopology& topology, const Eigen::MatrixXd& UV,
                       const DistortionMeasures& measures, bool converged, const MoldQualityLimits& limits);

}  // namespace lastcut
