#pragma once
// The daemon's side of the systemd service contract (sd_notify(3)): READY=1 once recovery is
// done and the folder is watched, STATUS= for `systemctl status`, WATCHDOG=1 only while the
// pipeline makes progress, RELOADING=1 / STOPPING=1 around SIGHUP and SIGTERM. Without systemd
// (NOTIFY_SOCKET unset) every call does nothing.
#include <chrono>
#include <string>

namespace lastcut::daemon {

class SystemdNotifier {
 public:
  SystemdNotifier();
  void ready();
  void reloading();
  void stopping();
  void status(const std::string& text);
  // Sends WATCHDOG=1 when half the watchdog interval has passed since the last one.
  void feed_watchdog(std::chrono::steady_clock::time_point now);
  bool watchdog_enabled() const { return watchdog_interval_.count() > 0; }

 private:
  std::chrono::microseconds watchdog_interval_{0};
  std::chrono::steady_clock::time_point last_feed_{};
  std::string last_status_;
};

}  // namespace lastcut::daemon
