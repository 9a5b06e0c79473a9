#pragma once
// ChildProcess: a real program a test (or benchmark) starts with fork/exec, its stdout and stderr
// appended to a log file, signalled and waited for with a deadline; killed (SIGKILL) by the
// destructor if still running. Used by the daemon harness (lastcutd, lastcut, lastcut-sim), the
// driver tests' simulators, the mosquitto broker and the PostgreSQL server of the tests, and the
// grbl throughput bench.
#include <filesystem>
#include <string>
#include <vector>

namespace lastcut::test {

class ChildProcess {
 public:
  // argv[0] is the program: a path, or a name looked up on PATH. The child starts with an empty
  // signal mask and without the test runner's JOURNAL_STREAM and NOTIFY_SOCKET. When exec fails the
  // child exits with 127 (the log says why). With end_with_parent the child gets SIGTERM when the
  // thread that started it ends (a test killed by CTest's timeout never reaches the destructor: a
  // simulator must not outlive it holding its pty link or port; start such a child from a thread
  // that outlives it), and it runs in a process group of its own: signals go to the whole group,
  // and what is left of the group when the child has ended is killed with it (stop, destructor).
  ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& log_file,
               bool end_with_parent = false);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  int pid() const { return pid_; }
  void signal(int number) const;
  // Waits for the exit; returns the exit status (or 128 + signal), -1 on timeout.
  int wait(double timeout_s);
  // SIGTERM, then wait (SIGKILL after kill_after_s); returns the exit status as wait() does.
  int stop(double kill_after_s = 5);
  bool running();

 private:
  void end_group();

  int pid_ = -1;
  int status_ = -1;
  bool exited_ = false;
  bool group_ = false;  // end_with_parent: the child leads a process group
};

// Runs argv to completion (at most timeout_s, then SIGKILL); returns the exit status, -1 on timeout.
int run_to_exit(const std::vector<std::string>& argv, const std::filesystem::path& log_file, double timeout_s);

}  // namespace lastcut::test
