// The nester on small instances: every layout passes the independent Clipper checker, every piece
// is placed or reported, results are deterministic for a seed, thread count and round budget, and
// the layout only improves (anytime).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "engine/core/engine_error.hpp"
#include "engine/nest/layout_check.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/nest/nester.hpp"
#include "nest_test_instances.hpp"

namespace lastcut {
namespace {

void run_on_threads(std::vector<std::function<void()>>& tasks) {
  std::vector<std::thread> threads;
  for (auto& task : tasks) threads.emplace_back(task);
  for (auto& t : threads) t.join();
}

NestOptions rounds(long n, int threads = 1, std::uint64_t seed = 1) {
  NestOptions options;
  options.time_limit_s = 60;  // never reached: the round budget ends the search
  options.iteration_limit = n;
  options.threads = threads;
  options.seed = seed;
  if (threads > 1) options.run_parallel = run_on_threads;
  return options;
}

void expect_valid(const Layout& layout, const NestInstance& instance, const NestOptions& options = {}) {
  const auto problems = check_layout(layout, instance, options.gap_mm.value_or(-1), options.margin_mm.value_or(-1));
  EXPECT_TRUE(problems.empty()) << problems.front();
}

TEST(Nester, StripLayoutIsValidAndImprovesOnTheGreedyStart) {
  const NestInstance instance = test::small_strip();
  std::vector<double> lengths;
  NestOptions options = rounds(15);
  options.on_improvement = [&](const Layout& layout) {
    lengths.push_back(*layout.strip_length);
    expect_valid(layout, instance);
  };
  const Layout layout = nest(instance, options);
  expect_valid(layout, instance);
  EXPECT_EQ(layout.placements.size(), 10u);
  EXPECT_TRUE(layout.unplaced.empty());
  ASSERT_GE(lengths.size(), 2u);  // a greedy start, then at least one shrink
  for (size_t i = 1; i < lengths.size(); ++i) EXPECT_LT(lengths[i], lengths[i - 1]);
  EXPECT_DOUBLE_EQ(*layout.strip_length, lengths.back());
  // Total piece area 3*1200 + 3*(50*12+28*12) + 4*390 = 7968 mm^2 on a 100 mm strip: at least 70 %.
  EXPECT_GT(layout.utilisation, 0.70);
}

TEST(Nester, SameSeedAndRoundsGiveTheSameLayoutOnAnyNumberOfThreads) {
  const NestInstance instance = read_nest_instance(LASTCUT_SHARED_DATA_DIR "/nesting/esicup/fu.json");
  const Layout a = nest(instance, rounds(6, 2, 5));
  const Layout b = nest(instance, rounds(6, 1, 5));
  expect_valid(a, instance);
  EXPECT_EQ(layout_to_json(a, instance).dump(), layout_to_json(b, instance).dump());
  const Layout other_seed = nest(instance, rounds(6, 2, 6));
  expect_valid(other_seed, instance);
  EXPECT_NE(layout_to_json(a, instance)["placements"].dump(), layout_to_json(other_seed, instance)["placements"].dump());
}

// A budget of separation steps ends the search long before its time limit, and, like rounds, gives
// the same layout on any number of threads.
TEST(Nester, SweepLimitEndsTheSearchAndGivesTheSameLayoutOnAnyNumberOfThreads) {
  const NestInstance instance = read_nest_instance(LASTCUT_SHARED_DATA_DIR "/nesting/esicup/fu.json");
  auto steps = [](int threads) {
    NestOptions options = rounds(1, threads, 3);
    options.iteration_limit.reset();
    options.sweep_limit = 300;
    return options;
  };
  const auto start = std::chrono::steady_clock::now();
  const Layout a = nest(instance, steps(2));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0);  // limit: 60 s
  const Layout b = nest(instance, steps(1));
  expect_valid(a, instance);
  EXPECT_EQ(layout_to_json(a, instance).dump(), layout_to_json(b, instance).dump());
}

TEST(Nester, GapAndMarginAreKept) {
  NestInstance instance = test::small_strip();
  NestOptions options = rounds(8);
  options.gap_mm = 3;
  options.margin_mm = 5;
  const Layout layout = nest(instance, options);
  expect_valid(layout, instance, options);
  EXPECT_EQ(layout.placements.size(), 10u);
  // The checker with a larger gap must find pieces that are closer (proves the gap is tight, not huge).
  EXPECT_FALSE(check_layout(layout, instance, 12, 5).empty());
}

TEST(Nester, PiecesThatCannotFitAreReportedNotDropped) {
  NestInstance instance = test::small_strip();
  instance.items.push_back(test::item(9, test::rectangle(150, 120), 2));  // taller than the strip either way
  NestItem grain = test::item(10, test::rectangle(30, 10), 1, {45});
  grain.grain_deg = 0;
  grain.grain_tolerance_deg = 10;
  instance.items.push_back(grain);
  const Layout layout = nest(instance, rounds(5));
  expect_valid(layout, instance);
  ASSERT_EQ(layout.unplaced.size(), 2u);
  EXPECT_EQ(layout.unplaced[0].item, 9);
  EXPECT_EQ(layout.unplaced[0].count, 2);
  EXPECT_NE(layout.unplaced[0].reason.find("taller"), std::string::npos);
  EXPECT_NE(layout.unplaced[1].reason.find("grain"), std::string::npos);
}

TEST(Nester, GrainAndMirroringAreRespected) {
  NestInstance instance = test::small_strip();
  for (NestItem& item : instance.items) {
    item.allowed_rotations_deg.clear();  // free rotation, but the grain must lie along x within 5 deg
    item.grain_deg = 30;
    item.grain_tolerance_deg = 5;
    item.allow_mirror = true;
  }
  const Layout layout = nest(instance, rounds(10));
  expect_valid(layout, instance);
  EXPECT_EQ(layout.placements.size(), 10u);
}

TEST(Nester, HidesAvoidDefectsZonesAndEdges) {
  NestInstance instance = test::small_hide();
  Bin second = instance.bins[0];
  second.id = 8;
  instance.bins.push_back(second);
  NestOptions options = rounds(3, 2);
  options.gap_mm = 2;
  options.margin_mm = 4;
  const Layout layout = nest(instance, options);
  expect_valid(layout, instance, options);
  EXPECT_EQ(layout.placements.size(), 7u);
  EXPECT_EQ(used_bin_count(layout), 1);  // 7 pieces of 30,000 mm^2 fit one hide of ~110,000 mm^2
}

TEST(Nester, HidesReportWhatDoesNotFit) {
  NestInstance instance = test::small_hide();
  instance.items.push_back(test::item(5, test::rectangle(500, 40), 1, {}));  // longer than the hide
  instance.items[0].demand = 30;                                             // more than one hide holds
  const Layout layout = nest(instance, rounds(1));
  expect_valid(layout, instance);
  bool too_long = false, no_room = false;
  for (const Unplaced& u : layout.unplaced) {
    too_long |= u.item == 5 && u.reason.find("does not fit on any hide") != std::string::npos;
    no_room |= u.item == 0 && u.reason.find("no room left") != std::string::npos;
  }
  EXPECT_TRUE(too_long);
  EXPECT_TRUE(no_room);
}

TEST(Nester, LeatherBenchmarkInstanceIsValid) {
  const NestInstance instance = read_nest_instance(LASTCUT_SHARED_DATA_DIR "/nesting/leather/baldacci1.json");
  const Layout layout = nest(instance, rounds(1, 2));
  expect_valid(layout, instance);
  EXPECT_EQ(layout.placements.size(), 54u);
}

TEST(Nester, RefusesBadOptions) {
  const NestInstance instance = test::small_strip();
  NestOptions options;
  options.threads = 0;
  EXPECT_THROW(nest(instance, options), EngineError);
  options.threads = 1;
  options.sweep_workers = 0;
  EXPECT_THROW(nest(instance, options), EngineError);
  options.sweep_workers = 4;
  options.gap_mm = -1;
  EXPECT_THROW(nest(instance, options), EngineError);
  NestInstance empty = instance;
  empty.items.clear();
  EXPECT_THROW(nest(empty, NestOptions{}), EngineError);
}

}  // namespace
}  // namespace lastcut
