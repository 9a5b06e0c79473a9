// The hide rule (daemon/station/hide_policy.hpp): when a loaded hide is nested, and the order of
// the jobs offered to it.
#include <gtest/gtest.h>

#include "daemon/station/hide_policy.hpp"

namespace lastcut::daemon {
namespace {

TEST(HidePolicy, AHideWithNoWaitingJobStaysOnItsTable) {
  EXPECT_FALSE(hide_is_due(0, false, 1e6, 0));
  EXPECT_FALSE(hide_is_due(0, true, 1e6, 0));
}

TEST(HidePolicy, AHideWaitsForJobsStillComputingUpToTheWindow) {
  EXPECT_TRUE(hide_is_due(1, false, 0, 300));   // nothing else on the way
  EXPECT_FALSE(hide_is_due(1, true, 10, 300));  // more of its material is being computed
  EXPECT_TRUE(hide_is_due(1, true, 300, 300));  // ... but not longer than the window
}

TEST(HidePolicy, TheTicketsPriorityFirstThenTheOldest) {
  // Three jobs offered oldest first, the second with priority 1.
  const int oldest = hide_job_priority(0, 0, 3), second = hide_job_priority(1, 1, 3), newest = hide_job_priority(0, 2, 3);
  EXPECT_GT(second, oldest);
  EXPECT_GT(oldest, newest);
  EXPECT_EQ(kHideMaxJobs, 64);
}

}  // namespace
}  // namespace lastcut::daemon
