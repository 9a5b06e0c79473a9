#include "daemon/service/systemd_notify.hpp"

#include <cstdint>

#include <systemd/sd-daemon.h>

namespace lastcut::daemon {

SystemdNotifier::SystemdNotifier() {
  uint64_t usec = 0;
  if (sd_watchdog_enabled(0, &usec) > 0) watchdog_interval_ = std::chrono::microseconds(usec);
}

void SystemdNotifier::ready() { sd_notify(0, "READY=1"); }

void SystemdNotifier::reloading() { sd_notify(0, "RELOADING=1"); }

void SystemdNotifier::stopping() { sd_notify(0, "STOPPING=1\nSTATUS=stopping: finishing or holding the jobs in hand"); }

void SystemdNotifier::status(const std::string& text) {
  if (text == last_status_) return;
  last_status_ = text;
  sd_notify(0, ("STATUS=" + text).c_str());
}

void SystemdNotifier::feed_watchdog(std::chrono::steady_clock::time_point now) {
  if (!watchdog_enabled()) return;
  if (now - last_feed_ < watchdog_interval_ / 2) return;
  last_feed_ = now;
  sd_notify(0, "WATCHDOG=1");
}

}  // namespace lastcut::daemon
