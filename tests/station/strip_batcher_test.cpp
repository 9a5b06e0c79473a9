// The spool's waiting list of strip jobs (daemon/station/strip_batcher.hpp), driven by made-up
// times: each job's wait counts from its own add, a due group is handed out once, a job added
// twice waits once. The rule itself is batching_policy_test.cpp's.
#include <gtest/gtest.h>

#include "daemon/station/strip_batcher.hpp"
#include "tests/station/batch_rule_helpers.hpp"

namespace lastcut::daemon {
namespace {

using Clock = StripBatcher::Clock;
using testing::Ids;
using testing::ids_of;
using testing::rule;

Clock::time_point at_s(double seconds) {
  return Clock::time_point{} + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

WaitingJob job(const std::string& id, int pieces = 2, const std::string& material = "calf") {
  return {id, material, "cutter-1", pieces, 0};
}

TEST(StripBatcher, AGroupIsDueWhenItsOldestJobHasWaitedTheWindowOnTheCallersClock) {
  StripBatcher batcher;
  batcher.add(job("a"), at_s(100));
  batcher.add(job("b"), at_s(105));
  EXPECT_TRUE(batcher.take_due(at_s(109.9), rule(10, 0)).empty());
  EXPECT_EQ(batcher.waiting(), 2u);
  EXPECT_EQ(ids_of(batcher.take_due(at_s(110), rule(10, 0))), (Ids{{"a", "b"}}));
}

TEST(StripBatcher, ADueGroupIsHandedOutOnceAndALaterJobStartsItsOwnWait) {
  StripBatcher batcher;
  batcher.add(job("a"), at_s(0));
  EXPECT_EQ(ids_of(batcher.take_due(at_s(10), rule(10, 0))), (Ids{{"a"}}));
  EXPECT_EQ(batcher.waiting(), 0u);
  EXPECT_TRUE(batcher.take_due(at_s(30), rule(10, 0)).empty());
  batcher.add(job("b"), at_s(30));
  EXPECT_TRUE(batcher.take_due(at_s(39), rule(10, 0)).empty()) << "b's wait counts from its own add, not a's";
  EXPECT_EQ(ids_of(batcher.take_due(at_s(40), rule(10, 0))), (Ids{{"b"}}));
}

TEST(StripBatcher, AJobAddedTwiceWaitsOnceAndKeepsItsFirstTime) {
  // Recovery and a requeue may both route one computed job: it must not be nested twice.
  StripBatcher batcher;
  batcher.add(job("a"), at_s(0));
  batcher.add(job("a"), at_s(8));
  EXPECT_EQ(batcher.waiting(), 1u);
  EXPECT_EQ(ids_of(batcher.take_due(at_s(10), rule(10, 0))), (Ids{{"a"}}));
}

TEST(StripBatcher, AFullGroupIsDueAtOnceAndTheRestWaits) {
  StripBatcher batcher;
  for (const char* id : {"a", "b", "c"}) batcher.add(job(id, 4), at_s(0));
  EXPECT_EQ(ids_of(batcher.take_due(at_s(0), rule(60, 8))), (Ids{{"a", "b"}}));
  EXPECT_EQ(batcher.waiting(), 1u);
  EXPECT_EQ(ids_of(batcher.take_due(at_s(60), rule(60, 8))), (Ids{{"c"}}));
}

TEST(StripBatcher, ForcedEveryGroupIsDueAndMaterialsStayApart) {
  StripBatcher batcher;
  batcher.add(job("a", 2, "calf"), at_s(0));
  batcher.add(job("b", 2, "suede"), at_s(1));
  batcher.add(job("c", 2, "calf"), at_s(2));
  EXPECT_EQ(ids_of(batcher.take_due(at_s(3), rule(60, 0), true)), (Ids{{"a", "c"}, {"b"}}));
  EXPECT_EQ(batcher.waiting(), 0u);
}

}  // namespace
}  // namespace lastcut::daemon
