#pragma once
// ProgressMonitor: decides whether the systemd watchdog may be fed. Every worker thread
// reports when it starts a task, when the task shows progress (bytes acknowledged by a cutter)
// and when it ends. A task that runs past its limit without progress is a stuck stage: the
// daemon then stops feeding the watchdog, systemd restarts it, and recovery puts the job in
// hand back into the spool (computing again, or held when it was being cut).
#include <chrono>
#include <map>
#include <mutex>
#include <string>

namespace lastcut::daemon {

class ProgressMonitor {
 public:
  using Clock = std::chrono::steady_clock;

  // `worker` names the thread ("compute-1", "cutter bench-a"); `limit_s`: longest time allowed
  // without begin()/beat() before the stage counts as stuck.
  void begin(const std::string& worker, const std::string& task, double limit_s);
  void beat(const std::string& worker);
  void end(const std::string& worker);

  // Empty when every busy worker is within its limit, else "compute-1 stuck on job X for 612 s".
  std::string stuck(Clock::time_point now) const;

 private:
  struct Busy {
    std::string task;
    Clock::time_point last_progress;
    double limit_s = 0;
  };
  mutable std::mutex mutex_;
  std::map<std::string, Busy> busy_;
};

}  // namespace lastcut::daemon
