#include "engine/nest/hide_repack.hpp"

#include "engine/nest/nest_random.hpp"

namespace lastcut::nest_detail {
namespace {

constexpr int kSamples = 240;


}  // namespace

bool repack_hides(const NestInstance& instance, const HidePieces& pieces, std::vector<int>& slot_of,
                  std::vector<PieceState>& state, const std::vector<int>& slots, const std::vector<int>& units,
                  std::uint64_t seed) {
  for (int u : units)
    for (int p : pieces.units[u]) slot_of[p] = -1;
  for (size_t k = 0; k < units.size(); ++k) {
    const std::vector<int>& members = pieces.units[units[k]];
    bool placed = false;
    for (int slot : slots) {
      bool all = true;
      for (size_t m = 0; m < members.size() && all; ++m) {
        Separator::Objective objective = [](const Box& b) { return b.x1 + 1e-3 * b.y0; };
        if (m > 0) objective = near_piece(pieces, members[0], slot, state[members[0]]);
        all = place_on_slot(pieces, members[m], slot, slot_of, state, objective, m == 0 ? kSamples : 2 * kSamples,
                            stream_seed(seed, k, m));
      }
      if (all && unit_near(pieces, instance, units[k], slot, state)) {
        placed = true;
        break;
      }
      for (int p : members) slot_of[p] = -1;
    }
    if (!placed) return false;
  }
  return true;
}

double concentration(const HidePieces& pieces, const std::vector<int>& slot_of) {
  std::vector<double> placed(pieces.slots.size(), 0);
  for (size_t i = 0; i < slot_of.size(); ++i)
    if (slot_of[i] >= 0) placed[slot_of[i]] += pieces.frames[0][pieces.item_of[i]].area_mm2;
  double sum = 0;
  for (size_t s = 0; s < placed.size(); ++s) sum += placed[s] * placed[s] / pieces.slots[s].container->usable_area_mm2();
  return sum;
}

}  // namespace lastcut::nest_detail
