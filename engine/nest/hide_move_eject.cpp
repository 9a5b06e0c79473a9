// The ejection chain of the hide search (engine/nest/hide_eject): the used hides emptied in turn,
// least filled first, into the others by separation, ejecting what cannot be separated; on every
// other turn an unused smaller hide, no dearer, joins the destinations (a big hide replaced by a
// smaller one). At the area bound only the replacing turns are tried. Kept when the hide is empty,
// or when the chain stopped early and put the rest back but the hides got more concentrated.
#include "engine/nest/hide_eject.hpp"
#include "engine/nest/hide_moves.hpp"

namespace lastcut::nest_detail {

bool eject_chain(HideSearchState& s, const MoveStep& step, const MoveContext& context) {
  const std::vector<int> order = s.targets();
  const EjectBudget budget = chain_budget(step.effort, context.tuning);
  const EjectTurn turn = eject_turn(context.instance, context.pieces, order, step.turn, order.size() <= s.area_bound());
  if (turn.target < 0) return false;
  const double before = s.concentration();
  HidePlacement& a = s.edit();
  switch (eject_hide(context.instance, context.pieces, context.options, context.deadline, a.slot_of, a.state, turn.target,
                     turn.destinations, step.seed, budget)) {
    case EjectResult::Emptied: return true;
    case EjectResult::Rearranged: return s.concentration() > before * (1 + 1e-9);
    case EjectResult::Failed: return false;
  }
  return false;
}

}  // namespace lastcut::nest_detail
