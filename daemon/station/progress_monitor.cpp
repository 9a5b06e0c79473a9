#include "daemon/station/progress_monitor.hpp"

namespace lastcut::daemon {

void ProgressMonitor::begin(const std::string& worker, const std::string& task, double limit_s) {
  std::lock_guard lock(mutex_);
  busy_[worker] = Busy{task, Clock::now(), limit_s};
}

void ProgressMonitor::beat(const std::string& worker) {
  std::lock_guard lock(mutex_);
  if (auto it = busy_.find(worker); it != busy_.end()) it->second.last_progress = Clock::now();
}

void ProgressMonitor::end(const std::string& worker) {
  std::lock_guard lock(mutex_);
  busy_.erase(worker);
}

std::string ProgressMonitor::stuck(Clock::time_point now) const {
  std::lock_guard lock(mutex_);
  for (const auto& [worker, busy] : busy_) {
    const double idle_s = std::chrono::duration<double>(now - busy.last_progress).count();
    if (idle_s > busy.limit_s) {
      return worker + " stuck on " + busy.task + " for " + std::to_string(static_cast<long long>(idle_s)) + " s";
    }
  }
  return {};
}

}  // namespace lastcut::daemon
