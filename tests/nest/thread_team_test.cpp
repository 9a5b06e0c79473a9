// ThreadTeam (daemon/cli/thread_team.hpp): the threads `lastcut nest` and nest_bench hand a sweep's tasks to.
#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <thread>
#include <vector>

#include "daemon/cli/thread_team.hpp"

namespace {

// Every task of every batch runs exactly once and is finished when run() returns, also with more
// tasks than threads and with batches of one task.
TEST(ThreadTeam, RunsEveryTaskOnceBeforeReturning) {
  lastcut::ThreadTeam team(2);
  for (int batch = 0; batch < 300; ++batch) {
    const size_t count = 1 + static_cast<size_t>(batch % 6);
    std::vector<std::atomic<int>> runs(count);
    std::vector<std::function<void()>> tasks;
    for (size_t t = 0; t < count; ++t) tasks.push_back([&runs, t] { runs[t].fetch_add(1); });
    team.run(tasks);
    for (size_t t = 0; t < count; ++t) ASSERT_EQ(runs[t].load(), 1) << "batch " << batch << " task " << t;
  }
}

// With one helper, two tasks run on two different threads (the point of the team), the first on the caller's.
TEST(ThreadTeam, SecondTaskRunsOnAHelperThread) {
  lastcut::ThreadTeam team(1);
  std::thread::id first, second;
  std::vector<std::function<void()>> tasks = {[&] { first = std::this_thread::get_id(); },
                                              [&] { second = std::this_thread::get_id(); }};
  team.run(tasks);
  EXPECT_EQ(first, std::this_thread::get_id());
  EXPECT_NE(second, std::this_thread::get_id());
  EXPECT_NE(second, std::thread::id());
}

// A team without helpers runs everything on the caller's thread.
TEST(ThreadTeam, NoHelpersRunsOnCaller) {
  lastcut::ThreadTeam team(0);
  std::set<std::thread::id> seen;
  std::vector<std::function<void()>> tasks(3, [&] { seen.insert(std::this_thread::get_id()); });
  team.run(tasks);
  EXPECT_EQ(seen, std::set<std::thread::id>{std::this_thread::get_id()});
}

}  // namespace
