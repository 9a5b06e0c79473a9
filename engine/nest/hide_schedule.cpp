// The hide search's schedule of moves; see hide_schedule.hpp.
#include "engine/nest/hide_schedule.hpp"

#include <span>

namespace lastcut::nest_detail {

ScheduledMove scheduled_move(long step, int level, bool at_area_bound) {
  const std::span<const ScheduleEntry> table = at_area_bound ? std::span<const ScheduleEntry>(schedule::kAtAreaBound)
                                               : level == 0  ? std::span<const ScheduleEntry>(schedule::kLevelZero)
                                                             : std::span<const ScheduleEntry>(schedule::kLaterLevels);
  const ScheduleEntry entry = table[static_cast<size_t>(step) % table.size()];
  const long attempt = step / 2;  // every table alternates a move and a chain
  switch (entry.turn) {
    case TurnRule::Attempt: return {entry.move, attempt};
    case TurnRule::AttemptOver3: return {entry.move, attempt / 3};
    case TurnRule::AttemptOver4: return {entry.move, attempt / 4};
    case TurnRule::Chain: return {entry.move, attempt - (attempt + 1) / 3};
  }
  return {entry.move, attempt};
}

}  // namespace lastcut::nest_detail
