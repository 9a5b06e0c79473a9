// The separation search on its own: sparrow's placement search for one piece and the multi-worker
// guided local search, on a rectangle container, checked with the exact collision test.
#include <gtest/gtest.h>

#include <thread>

#include "engine/nest/nest_geometry.hpp"
#include "engine/nest/overlap_proxy.hpp"
#include "engine/nest/parallel_separation.hpp"
#include "engine/nest/placement_search.hpp"
#include "engine/nest/strip_container.hpp"
#include "tests/nest/nest_test_instances.hpp"

namespace lastcut::nest_detail {
namespace {

bool collide(const PreparedItem& a, const PieceState& sa, const PreparedItem& b, const PieceState& sb) {
  const OrientedShape& x = a.orientations[sa.orientation];
  const OrientedShape& y = b.orientations[sb.orientation];
  return rings_collide({&x.outline, x.box, sa.offset, nullptr}, {&y.outline, y.box, sb.offset, nullptr});
}

void run_on_threads(std::vector<std::function<void()>>& tasks) {
  std::vector<std::thread> threads;
  for (size_t i = 1; i < tasks.size(); ++i) threads.emplace_back(tasks[i]);
  tasks[0]();
  for (auto& t : threads) t.join();
}

TEST(OverlapProxy, SumsEveryPolePairLikeThePlainFormula) {
  // Two L-shapes (5 and more poles, so the padded lanes are exercised) overlapping at a corner, and
  // the same pair far apart but for one pole pair: the four-lane sum must match the plain double sum.
  const PreparedItem a = prepare_item(test::item(0, test::l_shape(50, 40, 12), 1, {0}), 0, 0.0, 15);
  const PreparedItem b = prepare_item(test::item(1, test::l_shape(30, 30, 9), 1, {90}), 1, 0.0, 15);
  const OrientedShape& sa = a.orientations[0];
  const OrientedShape& sb = b.orientations[0];
  ASSERT_GE(sb.poles.size(), 2u);
  ASSERT_EQ(sb.pole_lanes.radius.size() % 4, 0u);
  for (const Point2& offset_b : {Point2(20, 15), Point2(45, 30), Point2(400, -300)}) {
    const double eps = 0.5;
    double plain = eps * eps;
    for (const Pole& p : sa.poles)
      for (const Pole& q : sb.poles) {
        const double pd = p.radius_mm + q.radius_mm - (p.center - q.center - offset_b).norm();
        plain += smoothed_depth(pd, eps) * std::min(p.radius_mm, q.radius_mm);
      }
    const double lanes = pair_overlap(sa, Point2::Zero(), sb, offset_b, eps);
    EXPECT_NEAR(lanes, plain, 1e-4 * plain) << offset_b.transpose();
  }
  // Deeper overlap measures more.
  EXPECT_GT(pair_overlap(sa, Point2::Zero(), sb, Point2(5, 5), 0.5), pair_overlap(sa, Point2::Zero(), sb, Point2(30, 20), 0.5));
}

TEST(PlacementSearch, MovesAPieceOffAnotherIntoTheFreeHalfAndNeverDoesWorse) {
  // A 100 x 50 box holding a 40 x 40 square at the left; a second square starts right on top of it.
  const PreparedItem square = prepare_item(test::item(0, test::rectangle(40, 40), 1, {0}), 0, 0.0, 15);
  const StripContainer box(100, 50, 0);
  const PieceState fixed{0, Point2(5, 5)};
  auto cost = [&](const PieceState& s, double) {
    const OrientedShape& shape = square.orientations[s.orientation];
    double c = box.exterior_overlap(shape, s.offset, 0, 0.4);
    if (collide(square, s, square, fixed)) c += std::sqrt(pair_overlap(shape, s.offset, shape, fixed.offset, 0.4));
    return c;
  };
  Random random(3);
  const PieceState start{0, Point2(8, 6)};
  const double start_cost = cost(start, 0);
  ASSERT_GT(start_cost, 0);
  const auto [found, found_cost] = search_placement(square, start, box, cost, SearchSettings{}, random);
  EXPECT_LE(found_cost, start_cost);
  EXPECT_EQ(found_cost, 0);  // there is room for it: x in [45, 60]
  EXPECT_FALSE(collide(square, found, square, fixed));
  EXPECT_GE(found.offset.x(), 45 - 1e-9);
}

TEST(ParallelSeparation, FourWorkersSeparateAPileAlikeOnOneOrTwoThreads) {
  // Six 30 x 20 rectangles piled at one spot of a 100 x 50 box (area 3600 of 5000: room to spare).
  const PreparedItem piece = prepare_item(test::item(0, test::rectangle(30, 20), 6, {0, 90}), 0, 0.0, 15);
  const std::vector<const PreparedItem*> pieces(6, &piece);
  const StripContainer box(100, 50, 0);
  auto separate = [&](std::uint64_t seed, int threads, std::vector<PieceState>& result) {
    ParallelSeparation separation(pieces, box, seed, 4, threads, run_on_threads);
    separation.set_state(std::vector<PieceState>(6, PieceState{0, Point2(10, 10)}));
    const bool separated = separation.separate(3, 100, Deadline(60));
    result = separation.state();
    return separated;
  };
  std::vector<PieceState> a, b;
  ASSERT_TRUE(separate(7, 2, a));
  for (size_t i = 0; i < a.size(); ++i) {
    const Box world = piece.orientations[a[i].orientation].box.shifted(a[i].offset);
    EXPECT_TRUE((Box{0, 0, 100, 50}.contains(world)));
    for (size_t j = i + 1; j < a.size(); ++j) EXPECT_FALSE(collide(piece, a[i], piece, a[j])) << i << " " << j;
  }
  ASSERT_TRUE(separate(7, 1, b));
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].orientation, b[i].orientation);
    EXPECT_EQ(a[i].offset, b[i].offset);
  }
}

}  // namespace
}  // namespace lastcut::nest_detail
