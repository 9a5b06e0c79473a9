#pragma once
// JobFlow: what lastcutd's main loop drives (daemon/lastcutd/main.cpp), in this order: set_observer,
// start, then per turn read_events / tick / stuck / status_line, reload on SIGHUP, stop on SIGTERM.
// One flow exists: Station (station.hpp), on one of two stores: SpoolStore (one station on its own
// file spool) or LedgerNode (one node of a shop sharing a PostgreSQL job ledger, chosen by [ledger]).
#include <chrono>
#include <memory>
#include <string>

#include "daemon/config/daemon_config.hpp"
#include "daemon/job/status_observer.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

class JobFlow {
 public:
  using Clock = std::chrono::steady_clock;

  virtual ~JobFlow() = default;
  // Live status (optional, daemon/status): set before start(); must outlive stop().
  virtual void set_observer(StatusObserver* observer) = 0;
  // Prepares storage, recovers what a crash left, starts watching and the worker threads; one line on failure.
  virtual Status start() = 0;
  // One turn of the main loop (every 100 ms at least): new files and whatever is due.
  virtual void tick(Clock::time_point now) = 0;
  // inotify descriptor to wait on (-1 when polling), and reading its events without blocking.
  virtual int event_fd() const = 0;
  virtual void read_events() = 0;
  // Empty while every stage makes progress; otherwise what is stuck (then the watchdog starves).
  virtual std::string stuck(Clock::time_point now) const = 0;
  // One line for systemd's STATUS= and the log.
  virtual std::string status_line() const = 0;
  // Applies a new, already validated configuration as far as it can while running; the returned
  // line says what waits for a restart ("" when everything applied).
  virtual std::string reload(std::shared_ptr<const DaemonConfig> config) = 0;
  // SIGTERM: stops taking work, lets cuts in hand finish for jobs.stop_grace_s (then they are held).
  virtual void stop() = 0;
};

}  // namespace lastcut::daemon
