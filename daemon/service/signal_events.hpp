#pragma once
// SIGTERM, SIGINT and SIGHUP delivered through a signalfd, so the main loop handles them in
// its own thread between two ticks (no work in signal handlers, no lost signals).
namespace lastcut::daemon {

enum class SignalEvent { None, Stop, Reload };

class SignalEvents {
 public:
  // Blocks the signals in the calling thread (call before starting any thread, so every
  // thread inherits the mask) and opens the signalfd.
  SignalEvents();
  ~SignalEvents();
  SignalEvents(const SignalEvents&) = delete;
  SignalEvents& operator=(const SignalEvents&) = delete;

  int fd() const { return fd_; }
  // Reads one pending signal without blocking.
  SignalEvent read();

 private:
  int fd_ = -1;
};

}  // namespace lastcut::daemon
