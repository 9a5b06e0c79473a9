// FdTransport: poll(2)-based reads and writes with timeouts on a non-blocking descriptor.
#include "drivers/transport/fd_transport.hpp"
#include "drivers/seconds_text.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <termios.h>
#include <thread>
#include <unistd.h>

namespace lastcut::drivers {

namespace {

int to_poll_ms(double timeout_s) {
  if (timeout_s <= 0) return 0;
  const double ms = timeout_s * 1000.0;
  return ms > 2.0e9 ? 2000000000 : static_cast<int>(ms + 0.999);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

FdTransport::FdTransport(int fd, std::string description, int wire_baud, bool is_tty, bool owns_fd)
    : fd_(fd), description_(std::move(description)), wire_baud_(wire_baud), is_tty_(is_tty), owns_fd_(owns_fd) {
  const int flags = ::fcntl(fd_, F_GETFL);
  if (flags >= 0) ::fcntl(fd_, F_SETFL, flags | O_NONBLOCK);
}

FdTransport::~FdTransport() { FdTransport::close(); }

IoStatus FdTransport::read(std::string& out, double timeout_s) {
  if (fd_ < 0) return IoStatus::failure(description_ + ": link is closed", true);
  pollfd pfd{fd_, POLLIN, 0};
  const int ready = ::poll(&pfd, 1, to_poll_ms(timeout_s));
  if (ready < 0) {
    if (errno == EINTR) return IoStatus::success();
    return IoStatus::failure(description_ + ": " + std::strerror(errno));
  }
  if (ready == 0) return IoStatus::success();
  char buffer[4096];
  const ssize_t got = ::read(fd_, buffer, sizeof buffer);
  if (got > 0) {
    out.append(buffer, static_cast<size_t>(got));
    return IoStatus::success();
  }
  if (got == 0) return IoStatus::failure(description_ + ": connection closed by the device", true);
  if (errno == EAGAIN || errno == EINTR) return IoStatus::success();
  // EIO on a tty: the device (USB adapter, pty master) went away.
  return IoStatus::failure(description_ + ": connection lost (" + std::strerror(errno) + ")", true);
}

IoStatus FdTransport::write(std::string_view data, double timeout_s) {
  if (fd_ < 0) return IoStatus::failure(description_ + ": link is closed", true);
  const auto start = std::chrono::steady_clock::now();
  size_t done = 0;
  while (done < data.size()) {
    // Sockets: MSG_NOSIGNAL, so a plotter closing the connection is an error here, not a SIGPIPE
    // that kills the daemon.
    const ssize_t put = is_tty_ ? ::write(fd_, data.data() + done, data.size() - done)
                                : ::send(fd_, data.data() + done, data.size() - done, MSG_NOSIGNAL);
    if (put > 0) {
      done += static_cast<size_t>(put);
      continue;
    }
    if (put < 0 && errno != EAGAIN && errno != EINTR) {
      // EIO/ENXIO on a tty, EPIPE/ECONNRESET on a socket: the device went away, which the operator reads
      // as a lost connection whichever side (read or write) noticed it first.
      if (errno == EIO || errno == EPIPE || errno == ECONNRESET || errno == ENXIO)
        return IoStatus::failure(description_ + ": connection lost while writing (" + std::strerror(errno) + ")", true);
      return IoStatus::failure(description_ + ": write failed (" + std::strerror(errno) + ")");
    }
    const double left_s = timeout_s - seconds_since(start);
    if (left_s <= 0) {
      return IoStatus::failure(description_ + ": the device has not accepted data for " +
                               seconds_text(timeout_s) + " (flow control held or link stalled)");
    }
    pollfd pfd{fd_, POLLOUT, 0};
    if (::poll(&pfd, 1, to_poll_ms(left_s < 0.05 ? left_s : 0.05)) < 0 && errno != EINTR) {
      return IoStatus::failure(description_ + ": " + std::strerror(errno));
    }
    if (pfd.revents & (POLLERR | POLLHUP)) {
      return IoStatus::failure(description_ + ": connection lost while writing", true);
    }
  }
  return IoStatus::success();
}

IoStatus FdTransport::drain(double timeout_s) {
  if (fd_ < 0) return IoStatus::failure(description_ + ": link is closed", true);
  if (!is_tty_) return IoStatus::success();
  // tcdrain can block forever behind a held flow control line; poll the output queue instead.
  const auto start = std::chrono::steady_clock::now();
  while (true) {
    int queued = 0;
    if (::ioctl(fd_, TIOCOUTQ, &queued) != 0 || queued <= 0) return IoStatus::success();
    if (seconds_since(start) > timeout_s) {
      return IoStatus::failure(description_ + ": " + std::to_string(queued) + " bytes still queued after " +
                               seconds_text(timeout_s) + " (flow control held)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

void FdTransport::close() {
  if (fd_ >= 0 && owns_fd_) ::close(fd_);
  fd_ = -1;
}

}  // namespace lastcut::drivers
