#pragma once
// Which move the hide search (engine/nest/hide_search) makes on which attempt, as tables. An attempt's
// step is the number of attempts since the last success (a success starts the table again); the
// tables repeat. Every other step is a chain (an ejection chain that empties a hide, every third of
// them a merge of two hides into an unused one); the steps between are:
// - level 0 (no cycle over the used hides failed yet): move one unit onto a fuller hide;
// - from level 1 on: move, swap, re-pack and shrink in turn;
// - at the area bound (the used hides as few as their area allows): only shrinks and chains, which
//   there only replace a hide by a smaller one (no merge: no hide can go).
// Chains every other step: 3 and 1 measured worse; merges every third chain (docs/benchmarks-nest.md).
// A move's turn (which unit, partner or pair of hides it starts from) follows from the attempt
// (step / 2, the move-and-chain pairs before it) by the rule in its table entry. The rules are the
// measured schedule's, odd as some are (a move from level 1 on takes attempt / 3): layouts depend on them.
#include <array>
#include <cstddef>

namespace lastcut::nest_detail {

enum class MoveId { Move, Swap, Repack, Shrink, Eject, Merge };

enum class TurnRule {
  Attempt,         // attempt
  AttemptOver3,    // attempt / 3
  AttemptOver4,    // attempt / 4: the shrinks so far (one every fourth attempt)
  Chain,           // attempt - (attempt + 1) / 3: the chains so far that were not in a merge's step
};

struct ScheduleEntry {
  MoveId move;
  TurnRule turn;
};

struct ScheduledMove {
  MoveId move;
  long turn = 0;
};

namespace schedule {
using enum MoveId;
using enum TurnRule;
inline constexpr std::array<ScheduleEntry, 6> kLevelZero = {{
    {Move, Attempt}, {Eject, Chain}, {Move, Attempt}, {Eject, Chain}, {Move, Attempt}, {Merge, AttemptOver3},
}};
inline constexpr std::array<ScheduleEntry, 24> kLaterLevels = {{
    {Move, AttemptOver3},   {Eject, Chain},        {Swap, AttemptOver3},   {Eject, Chain},
    {Repack, AttemptOver3}, {Merge, AttemptOver3}, {Shrink, AttemptOver4}, {Eject, Chain},
    {Move, AttemptOver3},   {Eject, Chain},        {Swap, AttemptOver3},   {Merge, AttemptOver3},
    {Repack, AttemptOver3}, {Eject, Chain},        {Shrink, AttemptOver4}, {Eject, Chain},
    {Move, AttemptOver3},   {Merge, AttemptOver3}, {Swap, AttemptOver3},   {Eject, Chain},
    {Repack, AttemptOver3}, {Eject, Chain},        {Shrink, AttemptOver4}, {Merge, AttemptOver3},
}};
inline constexpr std::array<ScheduleEntry, 2> kAtAreaBound = {{{Shrink, Attempt}, {Eject, Chain}}};
}  // namespace schedule

// The move of attempt `step` (attempts since the last success) at effort `level`; at_area_bound: the
// used hides are as few as their area allows (or fewer than two).
ScheduledMove scheduled_move(long step, int level, bool at_area_bound);

}  // namespace lastcut::nest_detail
