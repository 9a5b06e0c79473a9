// The test helper itself: a simulator started by a test does not outlive the test process, also when
// the test is killed (as CTest does on a timeout) and never stops it.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "tests/drivers/sim_process.hpp"

namespace lastcut::drivers::testing {
namespace {

TEST(SimProcess, SimulatorEndsWhenTheTestProcessIsKilled) {
  TempDir dir;
  int report[2];
  ASSERT_EQ(::pipe(report), 0);
  // The orphaned simulator is handed to this process (not to PID 1), so it can be waited for here.
  ASSERT_EQ(::prctl(PR_SET_CHILD_SUBREAPER, 1), 0);
  const pid_t test = ::fork();
  ASSERT_GE(test, 0);
  if (test == 0) {  // the "test": starts a simulator, reports its pid, then hangs until killed
    ::setenv("TMPDIR", dir.path().c_str(), 1);  // its simulator's log is never removed by it: keep it in `dir`
    SimProcess sim({"grbl", "--link", dir / "grbl", "--time-scale", "0"});
    const int pid = sim.ready() ? sim.pid() : -1;
    if (::write(report[1], &pid, sizeof pid) != sizeof pid) ::_exit(1);
    for (;;) ::pause();
  }
  int sim_pid = -1;
  ASSERT_EQ(::read(report[0], &sim_pid, sizeof sim_pid), static_cast<ssize_t>(sizeof sim_pid));
  ASSERT_GT(sim_pid, 0);
  ::kill(test, SIGKILL);
  ::waitpid(test, nullptr, 0);
  bool ended = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (!(ended = ::waitpid(sim_pid, nullptr, WNOHANG) == sim_pid) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_TRUE(ended) << "lastcut-sim " << sim_pid << " outlived the killed test";
  if (!ended) {
    ::kill(sim_pid, SIGKILL);
    ::waitpid(sim_pid, nullptr, 0);
  }
  ::prctl(PR_SET_CHILD_SUBREAPER, 0);
  ::close(report[0]);
  ::close(report[1]);
}

TEST(SimProcess, ReadyMeansThisSimulatorsLinkExistsWhateverLogsOthersLeft) {
  // A killed test leaves its simulator's log behind; a later test process can get the same pid (CI
  // flaked so: "no such port" right after "ready"). Logs in the old pid-based naming, each saying ready:
  TempDir dir;
  std::vector<std::filesystem::path> stale;
  for (int n = 1; n <= 3; ++n) {
    stale.push_back(std::filesystem::temp_directory_path() /
                    ("lastcut-sim-" + std::to_string(::getpid()) + "-" + std::to_string(n) + ".log"));
    std::ofstream(stale.back()) << "ready: " << (dir / "elsewhere") << " -> /dev/pts/999\n";
  }
  SimProcess sim({"grbl", "--link", dir / "grbl", "--time-scale", "0"});
  ASSERT_TRUE(sim.ready()) << sim.ready_line();
  EXPECT_TRUE(std::filesystem::exists(dir / "grbl")) << sim.ready_line();
  EXPECT_NE(sim.ready_line().find(dir / "grbl"), std::string::npos) << sim.ready_line();
  EXPECT_EQ(sim.stop(), 0);
  for (const auto& path : stale) std::filesystem::remove(path);
}

}  // namespace
}  // namespace lastcut::drivers::testing
