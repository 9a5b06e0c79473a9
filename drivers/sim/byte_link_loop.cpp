// Event loop of the byte-stream simulators: wire model, device clock, faults, recording.
#include "drivers/sim/byte_link_loop.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <deque>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include "drivers/sim/sim_link.hpp"

namespace lastcut::drivers::sim {

namespace {

double since_start_s() {
  static const auto start = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct TimedByte {
  double at_s;
  char byte;
};

// One direction of the serial line: a byte is delivered 10 bit times after the previous one.
class Wire {
 public:
  explicit Wire(int baud) { set_baud(baud); }
  void set_baud(int baud) { byte_s_ = baud > 0 ? 10.0 / baud : 0.0; }
  void push(const char* data, size_t n, double now_s) {
    for (size_t i = 0; i < n; ++i) {
      free_at_s_ = std::max(free_at_s_, now_s) + byte_s_;
      queue_.push_back({free_at_s_, data[i]});
    }
  }
  bool ready(double now_s) const { return !queue_.empty() && queue_.front().at_s <= now_s; }
  TimedByte pop() {
    const TimedByte b = queue_.front();
    queue_.pop_front();
    return b;
  }
  double next_s() const { return queue_.empty() ? INFINITY : queue_.front().at_s; }
  void clear() { queue_.clear(); }
  size_t size() const { return queue_.size(); }

 private:
  double byte_s_ = 0;
  double free_at_s_ = 0;
  std::deque<TimedByte> queue_;
};

// The baud rate the client set on its end of the pty (both ends share one termios), 0 if unknown.
int client_baud(int slave_fd) {
  termios tio{};
  if (slave_fd < 0 || ::tcgetattr(slave_fd, &tio) != 0) return 0;
  static const std::pair<speed_t, int> kSpeeds[] = {{B1200, 1200},     {B2400, 2400},     {B4800, 4800},
                                                    {B9600, 9600},     {B19200, 19200},   {B38400, 38400},
                                                    {B57600, 57600},   {B115200, 115200}, {B230400, 230400},
                                                    {B460800, 460800}, {B921600, 921600}};
  const speed_t speed = ::cfgetospeed(&tio);
  for (const auto& [constant, baud] : kSpeeds) {
    if (constant == speed) return baud;
  }
  return 0;
}

}  // namespace

int run_byte_device(ByteDevice& device, const ByteLinkOptions& options, const std::atomic<bool>& stop,
                    ReadyCallback ready, std::string& error) {
  PtyLink pty;
  int listener = -1, client = -1;
  if (!options.link_path.empty()) {
    if (!open_pty_link(options.link_path, pty, error)) return 1;
    ready(options.link_path + " -> " + pty.slave_name);
  } else {
    listener = listen_loopback(options.tcp_port, error);
    if (listener < 0) return 1;
    ready("127.0.0.1:" + std::to_string(options.tcp_port));
  }
  // baud < 0: model the wire at whatever rate the client configured on the pty, as a real
  // device would have to be set to the same rate as its sender.
  const bool follow_client = options.baud < 0;
  int wire_baud = follow_client ? 9600 : options.baud;
  Wire inbound(wire_baud), outbound(wire_baud);
  std::string unsent;  // output the kernel did not take yet
  bool dropped = false, stalled = false;
  double last_record_s = 0;
  size_t recorded_lines = 0;
  auto io_fd = [&] { return pty.master >= 0 ? pty.master : client; };

  while (!stop.load()) {
    const double now = since_start_s();
    if (follow_client) {
      const int baud = client_baud(pty.slave_keep);
      if (baud > 0 && baud != wire_baud) {
        wire_baud = baud;
        inbound.set_baud(baud);
        outbound.set_baud(baud);
      }
    }
    // The device runs at the modelled arrival time of each byte, so its answers leave at the
    // time a real controller would send them, however late this process was woken.
    while (inbound.ready(now)) {
      const TimedByte b = inbound.pop();
      device.receive(b.byte, b.at_s);
      device.advance(b.at_s);
      const std::string out = device.take_output();
      if (!stalled && !out.empty()) outbound.push(out.data(), out.size(), b.at_s);
    }
    device.advance(now);
    const std::string out = device.take_output();
    if (!stalled && !out.empty()) outbound.push(out.data(), out.size(), now);
    while (outbound.ready(now)) unsent += outbound.pop().byte;
    if (!unsent.empty() && io_fd() >= 0) {
      const ssize_t put = ::write(io_fd(), unsent.data(), unsent.size());
      if (put > 0) unsent.erase(0, static_cast<size_t>(put));
      if (unsent.size() > (1 << 16)) unsent.clear();  // nobody is reading: the device's UART would drop it too
    }

    const size_t lines = device.lines_received();
    const Faults& f = options.faults;
    if (!dropped && f.drop_at_line != 0 && lines >= f.drop_at_line) {
      dropped = true;
      close_pty_link(pty);
      if (client >= 0) ::close(client);
      if (listener >= 0) ::close(listener);
      client = listener = -1;
      inbound.clear();
      outbound.clear();
    }
    if (!stalled && f.stall_at_line != 0 && lines >= f.stall_at_line) {
      stalled = true;
      inbound.clear();
      outbound.clear();
      unsent.clear();
    }
    if (!options.record_dir.empty() && lines != recorded_lines && now - last_record_s > 0.5) {
      device.write_record(options.record_dir);
      recorded_lines = lines;
      last_record_s = now;
    }

    // Bytes in between need no wake-up of their own (they are processed at their modelled
    // times anyway): waking at most every 0.5 ms for input keeps the loop cheap on a busy PC.
    double wake = std::min({std::max(inbound.next_s(), now + 0.0005), outbound.next_s(), device.next_event_s(), now + 0.05});
    if (!unsent.empty()) wake = std::min(wake, now + 0.002);
    const double wait_s = std::max(0.0, wake - since_start_s());
    pollfd fds[2];
    nfds_t count = 0;
    const int fd = io_fd();
    if (fd >= 0 && !stalled) fds[count++] = {fd, POLLIN, 0};
    if (listener >= 0 && client < 0) fds[count++] = {listener, POLLIN, 0};
    const timespec timeout{static_cast<time_t>(wait_s), static_cast<long>(std::fmod(wait_s, 1.0) * 1e9)};
    if (::ppoll(fds, count, &timeout, nullptr) <= 0) continue;
    for (nfds_t i = 0; i < count; ++i) {
      if (fds[i].fd == listener && (fds[i].revents & POLLIN)) {
        client = ::accept4(listener, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
        continue;
      }
      if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      char buffer[4096];
      const ssize_t got = ::read(fds[i].fd, buffer, sizeof buffer);
      if (got > 0) {
        inbound.push(buffer, static_cast<size_t>(got), since_start_s());
      } else if (client >= 0 && fds[i].fd == client && (got == 0 || (errno != EAGAIN && errno != EINTR))) {
        ::close(client);  // the sender hung up; wait for the next one
        client = -1;
      } else if (got < 0 && errno == EIO) {
        ::usleep(1000);   // pty without a client yet
      }
    }
  }
  if (!options.record_dir.empty()) device.write_record(options.record_dir);
  close_pty_link(pty);
  if (client >= 0) ::close(client);
  if (listener >= 0) ::close(listener);
  return 0;
}

}  // namespace lastcut::drivers::sim
