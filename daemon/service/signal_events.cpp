#include "daemon/service/signal_events.hpp"

#include <csignal>
#include <sys/signalfd.h>
#include <unistd.h>

namespace lastcut::daemon {

SignalEvents::SignalEvents() {
  sigset_t mask;
  sigemptyset(&mask);
  sigaddset(&mask, SIGTERM);
  sigaddset(&mask, SIGINT);
  sigaddset(&mask, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &mask, nullptr);
  fd_ = ::signalfd(-1, &mask, SFD_NONBLOCK | SFD_CLOEXEC);
  // A closed cutter connection must come back as an error from write(), not kill the daemon.
  std::signal(SIGPIPE, SIG_IGN);
}

SignalEvents::~SignalEvents() {
  if (fd_ >= 0) ::close(fd_);
}

SignalEvent SignalEvents::read() {
  struct signalfd_siginfo info {};
  if (::read(fd_, &info, sizeof info) != static_cast<ssize_t>(sizeof info)) return SignalEvent::None;
  if (info.ssi_signo == SIGHUP) return SignalEvent::Reload;
  return SignalEvent::Stop;
}

}  // namespace lastcut::daemon
