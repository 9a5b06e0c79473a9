// The batching rule (daemon/station/batching_policy.hpp): by window, by pieces, per material and
// cutter, oldest first. The spool and the ledger both ask exactly this function.
#include <gtest/gtest.h>

#include "daemon/station/batching_policy.hpp"
#include "tests/station/batch_rule_helpers.hpp"

namespace lastcut::daemon {
namespace {

using testing::Ids;
using testing::ids_of;
using testing::rule;

TEST(BatchingPolicy, AWindowOfZeroNestsEachJobAloneAtOnce) {
  // However many wait together (a ledger node's worker may find several computed at once): alone.
  const std::vector<WaitingJob> waiting{{"a", "calf", "c1", 2, 0}, {"b", "calf", "c1", 2, 0}, {"c", "suede", "c1", 2, 0}};
  EXPECT_EQ(ids_of(due_batches(waiting, rule(0, 0))), (Ids{{"a"}, {"b"}, {"c"}}));
  EXPECT_EQ(ids_of(due_batches(waiting, rule(0, 8))), (Ids{{"a"}, {"b"}, {"c"}}));
}

TEST(BatchingPolicy, AGroupWaitsForItsWindowCountedFromItsOldestJob) {
  std::vector<WaitingJob> waiting{{"a", "calf", "c1", 2, 9.0}, {"b", "calf", "c1", 2, 1.0}};
  EXPECT_TRUE(due_batches(waiting, rule(10, 0)).empty());
  waiting[0].waited_s = 10.0;
  EXPECT_EQ(ids_of(due_batches(waiting, rule(10, 0))), (Ids{{"a", "b"}}));
  waiting[0].waited_s = 0;
  EXPECT_EQ(ids_of(due_batches(waiting, rule(10, 0), true)), (Ids{{"a", "b"}}));  // forced
}

TEST(BatchingPolicy, AGroupClosesWhenItsPiecesReachMaxPiecesWithoutWaiting) {
  const std::vector<WaitingJob> waiting{
      {"a", "calf", "c1", 4, 0}, {"b", "calf", "c1", 4, 0}, {"c", "calf", "c1", 4, 0}, {"d", "calf", "c1", 4, 0}};
  // 8 pieces close a batch; "c" and "d" make a second full one.
  EXPECT_EQ(ids_of(due_batches(waiting, rule(300, 8))), (Ids{{"a", "b"}, {"c", "d"}}));
  // 10: a, b, c reach 12 >= 10 (the last job is never split); d waits for its window.
  EXPECT_EQ(ids_of(due_batches(waiting, rule(300, 10))), (Ids{{"a", "b", "c"}}));
}

TEST(BatchingPolicy, MaterialsAndCuttersNeverShareABatch) {
  const std::vector<WaitingJob> waiting{{"a", "calf", "c1", 2, 5},
                                        {"b", "lining", "c1", 2, 5},
                                        {"c", "calf", "c2", 2, 5},
                                        {"d", "calf", "c1", 2, 5}};
  EXPECT_EQ(ids_of(due_batches(waiting, rule(1, 0))), (Ids{{"a", "d"}, {"b"}, {"c"}}));
  const auto batches = due_batches(waiting, rule(1, 0));
  EXPECT_EQ(batches[1].material, "lining");
  EXPECT_EQ(batches[2].cutter, "c2");
  EXPECT_EQ(batches[0].pieces, 4);
}

TEST(BatchingPolicy, AJobWithoutACountCountsAsOnePiece) {
  const std::vector<WaitingJob> waiting{{"a", "calf", "c1", 0, 0}, {"b", "calf", "c1", 0, 0}};
  EXPECT_EQ(ids_of(due_batches(waiting, rule(300, 2))), (Ids{{"a", "b"}}));
}

}  // namespace
}  // namespace lastcut::daemon
