#pragma once
// Transport: one byte link to a cutter (serial port, pseudo-terminal or TCP socket).
// Protocols (grbl, HPGL) talk through this interface only, so they run unchanged over a
// USB serial adapter, a simulator's pty or a network plotter. No exceptions: every call
// returns an IoStatus whose `error` is one line an operator can read ([[nodiscard]]: ignoring one
// is a compile warning).
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace lastcut::drivers {

enum class FlowControl { None, XonXoff, RtsCts };

// Line settings for serial links (ignored by TCP).
struct SerialSettings {
  int baud = 115200;
  int data_bits = 8;      // 5..8
  char parity = 'N';      // 'N' none, 'E' even, 'O' odd
  int stop_bits = 1;      // 1 or 2
  FlowControl flow = FlowControl::None;
};

// Parses "none" | "xonxoff" | "rtscts"; returns false on anything else.
bool parse_flow_control(std::string_view text, FlowControl& flow);
std::string to_string(FlowControl flow);

struct [[nodiscard]] IoStatus {
  bool ok = true;
  bool closed = false;    // the other side went away (cable pulled, socket closed, pty gone)
  std::string error;      // empty when ok
  static IoStatus success() { return {}; }
  static IoStatus failure(std::string why, bool link_closed = false) { return {false, link_closed, std::move(why)}; }
};

class Transport {
 public:
  virtual ~Transport() = default;
  // Appends whatever arrives within timeout_s (0 = only what is already there) to `out`.
  // Returns ok with nothing appended on timeout; not ok when the link failed or closed.
  virtual IoStatus read(std::string& out, double timeout_s) = 0;
  // Writes all of `data`, waiting at most timeout_s for the link to accept it.
  virtual IoStatus write(std::string_view data, double timeout_s) = 0;
  // Waits until written bytes have left this computer (tcdrain); no-op for sockets.
  virtual IoStatus drain(double timeout_s) = 0;
  virtual void close() = 0;
  // "pty /tmp/sim-grbl 115200 8N1 none", "tcp 127.0.0.1:9100", ...
  virtual std::string describe() const = 0;
  // Bits per second on the wire, 0 when not rate limited (TCP). Used to pace software flow control.
  virtual int wire_baud() const = 0;
};

struct OpenResult {
  std::unique_ptr<Transport> transport;  // null on failure
  std::string error;
};

// Opens `port`: "tcp://host:port", "usb:VID:PID[:SERIAL]" (hex ids), a /dev/serial/by-id/ path,
// a device path like /dev/ttyUSB0, or a pseudo-terminal / symlink to one (a simulator's --link).
// Real serial ports go through libserialport; ptys, which libserialport cannot open, through termios.
OpenResult open_transport(const std::string& port, const SerialSettings& settings, double timeout_s);

}  // namespace lastcut::drivers
