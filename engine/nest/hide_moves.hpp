#pragma once
// The moves of the hide search (engine/nest/hide_search), one file each (hide_move_*.cpp), behind one
// signature: a move changes a copy of the search state in place and says whether the result is to be
// kept (a partial result when it fails: the caller drops the copy). Which move runs on which attempt
// is engine/nest/hide_schedule; the insertion of one unit, which most moves share, is
// hide_move_insert.cpp. All of them (but an emptying chain) raise the sum over hides of placed area x
// fill (hide_repack's concentration), so none undoes another.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/nest/hide_eject.hpp"
#include "engine/nest/hide_pieces.hpp"
#include "engine/nest/hide_regroup.hpp"
#include "engine/nest/hide_schedule.hpp"
#include "engine/nest/hide_search_state.hpp"
#include "engine/nest/hide_search_tuning.hpp"
#include "engine/nest/nest_options.hpp"

namespace lastcut::nest_detail {

// What every move reads and never changes.
struct MoveContext {
  const NestInstance& instance;
  const HidePieces& pieces;
  const NestOptions& options;
  const Deadline& deadline;
  const HideSearchTuning& tuning;
};

struct MoveStep {
  long attempt = 0;  // move-and-chain pairs since the last success (hide_schedule)
  long turn = 0;     // which unit, partner or pair of hides the move starts from (hide_schedule)
  std::uint64_t seed = 0;
  Effort effort;
};

using HideMoveFn = bool (*)(HideSearchState& state, const MoveStep& step, const MoveContext& context);

struct HideMove {
  const char* name;
  HideMoveFn apply;
};

// The hide an attempt works on: of `order` (HideSearchState::targets, the least filled first), each
// for tuning.per_target attempts.
inline int attempt_target(const std::vector<int>& order, long attempt, const MoveContext& context) {
  return order[static_cast<size_t>(attempt / context.tuning.per_target) % order.size()];
}

// The budget of one ejection chain or merge at this effort.
inline EjectBudget chain_budget(const Effort& effort, const HideSearchTuning& tuning) {
  return EjectBudget{effort.strikes, effort.stale_sweeps, tuning.chain_destinations + effort.level, tuning.max_ejections};
}

// --- The insertion of one unit (hide_move_insert.cpp) ---
// `unit` onto `slot`: at a free sampled spot if there is one, otherwise dropped in (at the hide's
// centre, from effort level 1 at a random pose) and the hide separated. False: no feasible result.
bool insert_unit(HideSearchState& state, int unit, int slot, std::uint64_t seed, const Effort& effort, const MoveContext& context);
// `unit` onto the first of `destinations` (those with free area for it) that takes it, at most
// effort.destinations of them tried.
bool insert_anywhere(HideSearchState& state, int unit, const std::vector<int>& destinations, std::uint64_t seed,
                     const Effort& effort, const MoveContext& context);
// Insert (knapsack form): a unit left over onto the used hides, most free area first, failing those
// onto the unused hides in opening order.
bool insert_left_over(HideSearchState& state, int unit, std::uint64_t seed, const MoveContext& context);

// --- The scheduled moves ---
// Move (hide_move_unit.cpp): one unit of the attempt's hide onto a hide at least as full.
bool move_unit(HideSearchState& state, const MoveStep& step, const MoveContext& context);
// Swap (hide_move_swap.cpp): one unit of the attempt's hide and a smaller unit of a hide at least as
// full change places.
bool swap_units(HideSearchState& state, const MoveStep& step, const MoveContext& context);
// Re-pack (hide_move_repack.cpp): the attempt's hide and a fuller one packed again by the greedy.
bool repack_pair(HideSearchState& state, const MoveStep& step, const MoveContext& context);
// Shrink (hide_move_shrink.cpp): every unit of a used hide onto an unused smaller one, no dearer.
bool shrink_hide(HideSearchState& state, const MoveStep& step, const MoveContext& context);
// Eject (hide_move_eject.cpp): an ejection chain empties one used hide into the others.
bool eject_chain(HideSearchState& state, const MoveStep& step, const MoveContext& context);
// Merge (hide_move_merge.cpp): two used hides emptied into the others plus the largest unused hide.
bool merge_pair(HideSearchState& state, const MoveStep& step, const MoveContext& context);

// By MoveId.
inline constexpr std::array<HideMove, 6> kHideMoves = {{
    {"move", &move_unit},
    {"swap", &swap_units},
    {"repack", &repack_pair},
    {"shrink", &shrink_hide},
    {"eject", &eject_chain},
    {"merge", &merge_pair},
}};
inline const HideMove& hide_move(MoveId id) { return kHideMoves[static_cast<size_t>(id)]; }

// --- Regrouping (hide_move_regroup.cpp) ---
// `state` (every unit placed) regrouped onto the first hides of the opening order, one fewer than it
// uses (engine/nest/hide_regroup), when they could hold its pieces at tuning.regroup_fill by area with
// at most tuning.regroup_units_per_hide units a hide on average; nullopt otherwise or when not found.
// Within tuning.regroup_time_share of the time left (at least tuning.regroup_min_s, unless less is
// left); `oracle` packs one hide (the hide search itself, handed in by it).
std::optional<HidePlacement> regroup_fewer(const HideSearchState& state, long round, const MoveContext& context,
                                           const HidePackingOracle& oracle);

}  // namespace lastcut::nest_detail
