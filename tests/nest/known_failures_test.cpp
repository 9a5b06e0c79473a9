// What the regrouping takes as known to fail without asking the packing oracle (engine/nest/known_failures).
#include <gtest/gtest.h>

#include "engine/nest/known_failures.hpp"

namespace lastcut::nest_detail {
namespace {

TEST(KnownFailures, ASupersetOfAFailedSetOnTheSameHideFails) {
  KnownFailures failures(3);
  failures.add(1, {2, 5}, 1);
  const std::vector<int>* subset = failures.failed_subset(1, {1, 2, 5, 9}, 1);
  ASSERT_NE(subset, nullptr);
  EXPECT_EQ(*subset, (std::vector<int>{2, 5}));
  EXPECT_NE(failures.failed_subset(1, {2, 5}, 1), nullptr);
}

TEST(KnownFailures, OtherSetsAndOtherHidesAreNotKnown) {
  KnownFailures failures(3);
  failures.add(1, {2, 5}, 1);
  EXPECT_EQ(failures.failed_subset(1, {2}, 1), nullptr) << "a subset of a failed set may fit";
  EXPECT_EQ(failures.failed_subset(1, {2, 6, 9}, 1), nullptr);
  EXPECT_EQ(failures.failed_subset(0, {2, 5}, 1), nullptr) << "another hide";
  EXPECT_EQ(failures.failed_subset(2, {1, 2, 5}, 1), nullptr);
}

TEST(KnownFailures, AShortQuestionsFailureDoesNotAnswerALongerOne) {
  KnownFailures failures(1);
  failures.add(0, {3, 4}, 1);
  EXPECT_EQ(failures.failed_subset(0, {3, 4, 7}, 4), nullptr);
  failures.add(0, {3, 4}, 4);  // asked again, four times as long, and failed again
  EXPECT_NE(failures.failed_subset(0, {3, 4, 7}, 4), nullptr);
  EXPECT_NE(failures.failed_subset(0, {3, 4, 7}, 1), nullptr);
}

TEST(KnownFailures, ASetAskedAgainLongerIsForgottenUntilItsNewAnswer) {
  KnownFailures failures(1);
  failures.add(0, {3, 4}, 1);
  failures.forget(0, {3, 4});
  EXPECT_EQ(failures.failed_subset(0, {3, 4, 7}, 1), nullptr);
}

}  // namespace
}  // namespace lastcut::nest_detail
