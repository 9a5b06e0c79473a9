// SimProcess / TempDir helpers for the driver tests (real processes, real files).
#include "tests/drivers/sim_process.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

namespace lastcut::drivers::testing {

std::string sim_binary() { return std::string(LASTCUT_BINARY_DIR) + "/bin/lastcut-sim"; }

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

SimProcess::SimProcess(std::vector<std::string> args) : SimProcess(sim_binary(), std::move(args)) {}

SimProcess::SimProcess(const std::string& binary, std::vector<std::string> args) {
  // A fresh, empty log of its own: a name made from the pid could meet the log that a killed test
  // process with the same (reused) pid left behind, and its old "ready:" line would be taken for
  // this simulator's before the link exists.
  std::string pattern = (std::filesystem::temp_directory_path() / "lastcut-sim-XXXXXX.log").string();
  const int fd = ::mkstemps(pattern.data(), 4);
  if (fd < 0) std::abort();
  ::close(fd);
  log_ = pattern;
  std::vector<std::string> argv{binary};
  argv.insert(argv.end(), args.begin(), args.end());
  child_ = std::make_unique<lastcut::test::ChildProcess>(argv, log_, /*end_with_parent=*/true);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  std::string text;
  while (std::chrono::steady_clock::now() < deadline) {
    text = read_file(log_);
    for (std::size_t start = 0, end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
      if (text.compare(start, 7, "ready: ") != 0) continue;
      ready_ = true;
      ready_line_ = text.substr(start, end + 1 - start);
      return;
    }
    if (!child_->running()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ready_line_ = text;
}

SimProcess::~SimProcess() {
  child_.reset();
  std::error_code ignored;
  std::filesystem::remove(log_, ignored);
}

int SimProcess::stop() {
  if (!child_ || !child_->running()) return -1;
  const int status = child_->stop(5);
  return status >= 0 && status < 128 ? status : -1;
}

int run_command(const std::string& command, std::string& output) {
  output.clear();
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return -1;
  char buffer[512];
  size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, got);
  const int status = ::pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace lastcut::drivers::testing
