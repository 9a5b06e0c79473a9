#pragma once
// SimProcess: runs the real `lastcut-sim` binary (or another real program) for a test, waits for its "ready:" line,
// and stops it with SIGTERM (checking it exits cleanly); it also gets SIGTERM when the test process dies
// without stopping it (a CTest timeout). TempDir: a fresh folder per test.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "tests/support/child_process.hpp"
#include "tests/support/loopback_port.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut::drivers::testing {

// tests/support/temp_dir.hpp's folder; `dir / "name"` is a string here, as the simulators' arguments are.
class TempDir : public lastcut::test::TempDir {
 public:
  TempDir() : lastcut::test::TempDir("drivers") {}
  std::string operator/(const std::string& name) const { return (path() / name).string(); }
};

class SimProcess {
 public:
  // args: everything after the program name, e.g. {"grbl", "--link", "/tmp/x/grbl"}.
  explicit SimProcess(std::vector<std::string> args);
  // Any other program that prints "ready: ..." when it is listening (the node Modbus server).
  SimProcess(const std::string& program, std::vector<std::string> args);
  ~SimProcess();
  SimProcess(const SimProcess&) = delete;
  SimProcess& operator=(const SimProcess&) = delete;

  bool ready() const { return ready_; }
  int pid() const { return child_ ? child_->pid() : -1; }
  // Its "ready: ..." line; when it never came, what the program printed instead.
  const std::string& ready_line() const { return ready_line_; }
  // SIGTERM, wait; returns the exit status (0 = clean), -1 if it had to be killed.
  int stop();

 private:
  std::filesystem::path log_;  // the program's stdout and stderr, removed with it
  std::unique_ptr<lastcut::test::ChildProcess> child_;
  bool ready_ = false;
  std::string ready_line_;
};

std::string sim_binary();
std::string read_file(const std::filesystem::path& path);
using lastcut::test::free_loopback_port;
// Runs a shell command, returns its exit status and captures stdout+stderr in `output`.
int run_command(const std::string& command, std::string& output);

}  // namespace lastcut::drivers::testing
