#pragma once
// Segmentation of an oriented last into its medial and lateral halves, the surfaces the molds are
// flattened from (thesis steps 2-5, Sabaliauskas 2017, "Computerized modeling technology of unique
// footwear surface manufacturing design", section 3.1).
//  1. scan holes up to max_hole_fill_diameter_mm across are closed with a faired patch (engine/mesh/fill_holes.hpp);
//  2. faces are classified by normal elevation into sole, sides and top, and the sole and the flat
//     top cut become one connected region each (surface_regions.hpp);
//  3. the mesh is cut along the feather line and the top rim (level_set_cut.hpp), so mold edges are
//     smooth curves, not staircases. The classification of step 2 alone places them where the
//     normal crosses +-45 degrees, which in the arch is reached so gradually that noise and sampling
//     moved the curve by millimetres; so the sole surface and the top plane are fitted to the
//     classified regions and the curves run at a fixed height above the sole and depth below the
//     top plane (contour_fields.hpp). Where a fit fails (not a last: a foot's toes) the 1/2 level
//     set of the region indicator after the eq. 22 moving average is used, as the thesis does;
//  4. those two cut curves, traced with Dijkstra (region_contour.hpp), place the split plane through
//     T1, T2, T3 as arc-length means (split_plane.hpp), or with SplitRule::Expert through the top
//     centre, the second toe and the heel middle as experts cut by hand (expert_split_plane.hpp),
//     and the mesh is cut along the plane.
//     Every step is measured in mm, not in vertices, so a denser or coarser scan of the same last
//     gives the same curves;
//  5. the faces between the curves on either side of the plane form the two halves, each checked
//     to be a topological disk (segment_halves.hpp).
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"
#include "engine/mesh/fill_holes.hpp"
#include "engine/orient/orient_last.hpp"
#include "engine/segment/expert_split_plane.hpp"
#include "engine/segment/split_plane.hpp"

namespace lastcut {

// Which lengthwise plane splits the last into its halves (docs/segmentation-expert.md).
enum class SplitRule {
  Auto,    // through T1, T2, T3 of the thesis's automatic method (section 3.1, split_plane.hpp)
  Expert,  // through the top centre, the second toe and the heel middle (section 2.1, expert_split_plane.hpp)
};

struct SegmentOptions {
  double sole_angle_rad = -std::numbers::pi / 4;  // faces at or below this elevation are sole (eq. 7)
  double top_angle_rad = std::numbers::pi / 4;    // faces at or above this elevation may be top (eq. 9)
  double plane_t = 1.0 / 3.0;                     // where the toe and heel parts of the sole contour end (eqs. 14-15)
  int smoothing_passes = 10;                      // eq. 22 moving-average passes on a 2 mm edge mesh (scaled to the same mm on others)
  double max_hole_fill_diameter_mm = 30;          // scan holes up to this size across are closed (fill_holes.hpp)
  // Where the sole and the top cut fit smooth shapes, the curves are placed by height, not angle:
  double feather_height_mm = 1.5;  // the feather line runs this high above the fitted sole surface
  double rim_depth_mm = 1.25;      // the top rim runs this deep below the fitted top plane
  SplitRule split_rule = SplitRule::Auto;
  ExpertSplitOptions expert;       // used with SplitRule::Expert
};

struct Segment {
  std::string name;                     // "medial" or "lateral"; kNeutralHalf* of an unnamed symmetric last
  TriMesh mesh;                         // topological disk, canonical frame, mm
  std::map<std::string, int> landmarks; // boundary vertex indices: "toe", "heel", "top_front", "top_back"
  MeshTopology topology;                // of mesh, handed on to flattening and the mold
};

struct Segmentation {
  Segment medial, lateral;  // an unnamed symmetric last (OrientedLast::side_unnamed): side_b (-Y), side_a (+Y)
  std::vector<HoleRepair> repairs;  // the scan holes closed (step 1)
  std::vector<std::string> notes;
  std::vector<Eigen::Vector3d> lower_contour;  // the smoothed feather line the halves were cut along, closed loop, mm
  std::vector<Eigen::Vector3d> upper_contour;  // the smoothed rim of the top cut, closed loop, mm
  SplitPlane plane;                            // the lengthwise plane the halves were cut along
};

// The last cut along the feather line and the top rim, before the lengthwise cut (steps 1-3): what
// every split plane shares, so that two rules can be compared on the same surface
// (segmentation_agreement.hpp).
struct BandCut {
  TriMesh mesh;            // the whole last after both cuts, canonical frame, mm
  Eigen::MatrixXd fields;  // #V x 3: sole, top and plane columns (CutField, segment_halves.hpp); the plane column is 0
  std::vector<Eigen::Vector3d> lower_loop, upper_loop;  // smoothed feather line and top rim the plane is placed from, mm
  double snap_fraction = 0;  // crossings of the plane this close to an edge end snap to it (level_set_cut.hpp)
  FootSide side = FootSide::Left;
  bool side_unnamed = false;        // OrientedLast::side_unnamed: the halves get neutral names
  std::vector<HoleRepair> repairs;  // the scan holes closed (step 1)
  std::vector<std::string> notes;
};

// last: an oriented last (engine/orient/orient_last.hpp); topology: of last.mesh, which has the
// scan's faces (MeshIntake::topology). Deterministic.
// Throws EngineError when a step fails (no sole, no top cut, a half that is not one sheet) or the
// topology was built for another mesh.
Segmentation segment_last(const OrientedLast& last, const MeshTopology& topology, const SegmentOptions& options = {});
// The same, building last.mesh's topology itself.
Segmentation segment_last(const OrientedLast& last, const SegmentOptions& options = {});

// The three stages of segment_last, for callers that split one last by more than one plane.
// Each throws EngineError like segment_last; topology as there.
BandCut cut_band(const OrientedLast& last, const MeshTopology& topology, const SegmentOptions& options = {});
BandCut cut_band(const OrientedLast& last, const SegmentOptions& options = {});
SplitPlane place_split_plane(const BandCut& band, const SegmentOptions& options = {});
Segmentation split_band(const BandCut& band, const SplitPlane& plane);

}  // namespace lastcut
