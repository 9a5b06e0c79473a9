// The merge of the hide search (engine/nest/hide_merge): two used hides emptied into the others plus
// the largest unused hide, when the hides left could hold the pieces by area (one hide fewer, fewer
// larger hides). Only when the used hides are more than their area needs.
#include "engine/nest/hide_merge.hpp"
#include "engine/nest/hide_moves.hpp"

namespace lastcut::nest_detail {

bool merge_pair(HideSearchState& s, const MoveStep& step, const MoveContext& context) {
  const std::vector<int> order = s.targets();
  if (order.size() <= s.area_bound()) return false;  // the schedule never asks for it there
  const EjectBudget budget = chain_budget(step.effort, context.tuning);
  const MergeTurn turn = merge_turn(context.instance, context.pieces, s.slot_of(), order, step.turn, context.tuning.merge_fill);
  HidePlacement& a = s.edit();
  return merge_hides(context.instance, context.pieces, context.options, context.deadline, a.slot_of, a.state, turn, step.seed,
                     budget);
}

}  // namespace lastcut::nest_detail
