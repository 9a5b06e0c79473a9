#pragma once
// The one way a batch of cutting-room orders becomes a nest instance and a layout, for every front
// door: the daemon (a strip batch, or the waiting pieces on the hide that lies on a cutter's table)
// and `lastcut nest molds/ --hides HIDE...`. Nothing outside the engine builds nest items for a
// batch or calls a nester variant: the caller gives the pieces grouped by job and gets back a layout
// checked by the independent checker (layout_check.hpp).
//
// Rules (docs/hides.md):
//   rotations  every piece may turn in steps of rotation_step_deg (0, step, 2 step, ... < 360), or
//              freely when the step is 0; a piece with a grain of its own turns freely within its
//              grain tolerance
//   priority   an older job first: the group's priority is copied onto its items (NestItem::priority)
//   leather    on hides, spec.min_quality for the whole piece, spec.toe_min_quality for its toe region,
//              grain along the hide's backbone within spec.grain_tolerance_deg; a piece that comes
//              with a grain of its own (a pattern or style piece, pattern_items.hpp) keeps its grain
//              and tolerance, a piece whose grain is free (a lining) stays free
//   pairs      on hides, a job's pieces are cut together or not at all, and with PairPolicy::SameHide
//              all jobs of one order (the left and right lasts of a pair) share one pair group, so
//              they lie on one hide; with PairPolicy::Any only a job's own pieces stay together;
//              anywhere on that hide, or side by side (BatchSpec::side_by_side); a group that may be
//              split (PieceGroup::may_split) is none of this: each of its pieces goes where it fits
// A pair group the nester cuts only in part (a piece unplaced, or its pieces on different hides) is
// taken out whole, the lowest priority first, and the rest nested again, so what is cut is always
// whole jobs, whatever the nester does with pair groups.
#include <optional>
#include <string>
#include <vector>

#include "engine/nest/layout.hpp"
#include "engine/nest/nest_options.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

// The pieces of one job (the daemon) or one set of molds (the command line).
struct PieceGroup {
  std::string owner;  // job id; names the group in reasons
  std::string order;  // the workshop's order; "" = the job stands alone
  int priority = 0;   // higher is placed first (the daemon: older jobs higher)
  std::vector<NestItem> items;  // ids are renumbered by the batch
  // On hides: the group's pieces may be cut in part, on whatever hides they fit (an order that allows
  // splitting); it joins no pair group, and the pieces left out wait for another hide.
  bool may_split = false;
};

enum class PairPolicy { SameHide, Any };

struct BatchSpec {
  int rotation_step_deg = 90;  // 1..360 (360 = no rotation); 0 = free rotation
  PairPolicy pairs = PairPolicy::SameHide;
  // A pair group's pieces next to each other (the nester's "near": centroids within their mean
  // diagonal plus the gap), or anywhere on their one hide (false). Side by side suits a pair of two
  // molds; a shoe's dozen pieces kept side by side leave the rest of a hide in scraps (measured:
  // 20 style pairs on the Baldacci hides, bench/nest/piece_yield_bench --relax near).
  bool side_by_side = false;
  double gap_mm = 0;     // between pieces
  double margin_mm = 0;  // to the material edge and defects
  // Hides only (leather grades: docs/hides.md).
  int min_quality = 0;  // every piece lies on this grade or better
  // The toe and vamp show on the finished shoe: a mold's region within toe_fraction of its toe-heel
  // distance from the toe notch (toe_region in mold_items.hpp) lies on this grade or better (0 = off).
  int toe_min_quality = 0;
  double toe_fraction = 0.4;
  // A shoe's piece and the other foot's copy of it on one hide moved to mirror places about its
  // backbone where they fit (engine/nest/hide_mirror_pairs.hpp); false leaves them as nested.
  bool mirror_pairs = true;
  // A piece's heel-to-toe axis (the mold's x axis) within this of the backbone, on hides that have
  // one (hides without a backbone leave the grain free). nullopt = off.
  std::optional<double> grain_tolerance_deg;
};

// A pair distance no hide reaches: "near" then means "on the same hide".
inline constexpr double kAnywhereOnOneHide_mm = 1e6;

struct BatchInstance {
  NestInstance instance;
  std::vector<int> group_of_item;  // instance.items[i] belongs to groups[group_of_item[i]]
  bool mirror_pairs = false;       // hides: BatchSpec::mirror_pairs
};

// The pieces on a strip of strip_height_mm. Throws EngineError on bad spec or empty groups.
BatchInstance strip_batch(const std::vector<PieceGroup>& groups, double strip_height_mm, const BatchSpec& spec,
                          const std::string& name);
// The pieces on `hides` (ids renumbered 0..). Throws EngineError on bad spec, no hides or empty groups.
BatchInstance hide_batch(const std::vector<PieceGroup>& groups, const std::vector<Bin>& hides, const BatchSpec& spec,
                         const std::string& name);

// nest() on the instance. On hides, while a pair group is cut only in part, the lowest-priority such
// group is taken out (its pieces listed as unplaced with the reason) and the others nested again
// (one more nest() each, so at most groups x time_limit_s); then pairs are mirrored about the
// backbone where they fit (batch.mirror_pairs); the final layout is checked again by the independent
// checker. Throws EngineError as nest().
Layout nest_batch(const BatchInstance& batch, const NestOptions& options);

// Indices of the groups with every piece placed.
std::vector<int> placed_groups(const BatchInstance& batch, const Layout& layout);

}  // namespace lastcut
