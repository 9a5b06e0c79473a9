// A child process for tests (see child_process.hpp).
#include "tests/support/child_process.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

namespace lastcut::test {

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& log_file,
                           bool end_with_parent) {
  if (argv.empty()) throw std::invalid_argument("ChildProcess: no program given");
  // Built before fork: the child only calls async-signal-safe functions until exec.
  std::vector<char*> args;
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  const std::string log = log_file.string();
  const pid_t parent = ::getpid();
  pid_ = ::fork();
  if (pid_ < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  if (pid_ > 0 && end_with_parent) {
    ::setpgid(pid_, pid_);  // also here: whichever of the two runs first
    group_ = true;
  }
  if (pid_ == 0) {
    if (end_with_parent) {
      ::setpgid(0, 0);  // a group of its own: what it starts (a pty bridge, a firmware) ends with it
      ::prctl(PR_SET_PDEATHSIG, SIGTERM);
      if (::getppid() != parent) ::_exit(1);  // the parent died before prctl took effect
    }
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      if (fd > 2) ::close(fd);
    }
    // Test processes must not inherit a blocked signal mask or the journal of the test runner.
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    ::unsetenv("JOURNAL_STREAM");
    ::unsetenv("NOTIFY_SOCKET");
    ::execvp(args[0], args.data());
    const char* message = "exec failed: ";
    (void)!::write(2, message, std::strlen(message));
    (void)!::write(2, args[0], std::strlen(args[0]));
    (void)!::write(2, "\n", 1);
    ::_exit(127);
  }
}

ChildProcess::~ChildProcess() {
  if (running()) {
    signal(SIGKILL);
    wait(5);
  }
  end_group();
}

void ChildProcess::signal(int number) const {
  if (pid_ > 0 && !exited_) ::kill(group_ ? -pid_ : pid_, number);
}

void ChildProcess::end_group() {
  // What the child started and left behind (an orphan would spin on after the test).
  if (group_ && pid_ > 0) ::kill(-pid_, SIGKILL);
  group_ = false;
}

bool ChildProcess::running() {
  if (exited_ || pid_ <= 0) return false;
  int status = 0;
  if (::waitpid(pid_, &status, WNOHANG) == pid_) {
    exited_ = true;
    status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return false;
  }
  return true;
}

int ChildProcess::wait(double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (running() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  return running() ? -1 : status_;
}

int ChildProcess::stop(double kill_after_s) {
  signal(SIGTERM);
  if (wait(kill_after_s) < 0) {
    signal(SIGKILL);
    wait(5);
  }
  end_group();
  return exited_ ? status_ : -1;
}

int run_to_exit(const std::vector<std::string>& argv, const std::filesystem::path& log_file, double timeout_s) {
  ChildProcess child(argv, log_file);
  const int status = child.wait(timeout_s);
  if (status < 0) child.stop(0);
  return status;
}

}  // namespace lastcut::test
