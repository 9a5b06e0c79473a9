#include "engine/nest/strip_moves.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lastcut::nest_detail {
namespace {

constexpr double kLargeAreaShare = 0.75;


const OrientedShape& shape_of(const std::vector<const PreparedItem*>& pieces, const std::vector<PieceState>& state,
                              size_t i) {
  return pieces[i]->orientations[state[i].orientation];
}

// Pieces (other than a and b) whose largest pole centre lies inside piece `cover` where it stands now.
std::vector<size_t> covered_by(const std::vector<const PreparedItem*>& pieces, const std::vector<PieceState>& state,
                               size_t cover, size_t a, size_t b) {
  const OrientedShape& c = shape_of(pieces, state, cover);
  const Box world = c.box.shifted(state[cover].offset);
  std::vector<size_t> result;
  for (size_t k = 0; k < pieces.size(); ++k) {
    if (k == a || k == b) continue;
    const OrientedShape& s = shape_of(pieces, state, k);
    if (s.poles.empty()) continue;
    const Point2 pole = s.poles.front().center + state[k].offset;
    if (pole.x() < world.x0 || pole.x() > world.x1 || pole.y() < world.y0 || pole.y() > world.y1) continue;
    if (point_in_ring(pole - state[cover].offset, c.outline)) result.push_back(k);
  }
  return result;
}

}  // namespace

void shrink_strip(const std::vector<const PreparedItem*>& pieces, std::vector<PieceState>& state, double split_x,
                  double delta_mm, const Container& container) {
  for (size_t i = 0; i < pieces.size(); ++i) {
    const OrientedShape& s = shape_of(pieces, state, i);
    if (s.box.shifted(state[i].offset).centre().x() > split_x) state[i].offset.x() -= delta_mm;
    state[i].offset = container.clamp_offset(s, state[i].offset);
  }
}

void disrupt_layout(const std::vector<const PreparedItem*>& pieces, std::vector<PieceState>& state,
                    const Container& container, Random& random) {
  const size_t n = pieces.size();
  if (n < 2) return;
  std::vector<size_t> by_area(n);
  std::iota(by_area.begin(), by_area.end(), size_t{0});
  std::stable_sort(by_area.begin(), by_area.end(), [&](size_t a, size_t b) { return pieces[a]->area_mm2 > pieces[b]->area_mm2; });
  double total = 0;
  for (const PreparedItem* p : pieces) total += p->area_mm2;
  double cumulative = 0, cutoff = 0;
  for (size_t i : by_area) {
    cumulative += pieces[i]->area_mm2;
    cutoff = pieces[i]->area_mm2;
    if (cumulative >= kLargeAreaShare * total) break;
  }
  std::vector<size_t> large;
  for (size_t i = 0; i < n; ++i)
    if (pieces[i]->area_mm2 >= cutoff) large.push_back(i);
  const size_t a = large[random.below(static_cast<int>(large.size()))];
  std::vector<size_t> partners;
  for (size_t i : large)
    if (std::abs(pieces[i]->area_mm2 - pieces[a]->area_mm2) > 0.01 * pieces[a]->area_mm2 &&
        std::abs(pieces[i]->diameter_mm - pieces[a]->diameter_mm) > 0.01 * pieces[a]->diameter_mm)
      partners.push_back(i);
  if (partners.empty())
    for (size_t i = 0; i < n; ++i)
      if (i != a) partners.push_back(i);
  const size_t b = partners[random.below(static_cast<int>(partners.size()))];

  const Point2 centre_a = shape_of(pieces, state, a).box.shifted(state[a].offset).centre();
  const Point2 centre_b = shape_of(pieces, state, b).box.shifted(state[b].offset).centre();
  const Point2 old_a = state[a].offset, old_b = state[b].offset;
  state[a].offset += centre_b - centre_a;
  state[b].offset += centre_a - centre_b;
  state[a].offset = container.clamp_offset(shape_of(pieces, state, a), state[a].offset);
  state[b].offset = container.clamp_offset(shape_of(pieces, state, b), state[b].offset);
  // What a swapped piece now covers moves into the room that piece left.
  for (const auto& [mover, old_offset] : {std::pair{a, old_a}, std::pair{b, old_b}}) {
    const Point2 back = old_offset - state[mover].offset;
    for (size_t k : covered_by(pieces, state, mover, a, b)) {
      state[k].offset += back;
      state[k].offset = container.clamp_offset(shape_of(pieces, state, k), state[k].offset);
    }
  }
}

}  // namespace lastcut::nest_detail
