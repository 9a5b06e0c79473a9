#pragma once
// ByteDevice: a simulated machine that talks bytes over a serial line (grbl, HPGL cutter).
// The link loop (link_loop.hpp) models the wire and calls these with simulated arrival times;
// devices are pure state machines driven by time, so they can also be tested without a link.
#include <cstddef>
#include <filesystem>
#include <limits>
#include <string>

namespace lastcut::drivers::sim {

// Faults a simulated device can inject, counted in program lines (grbl) or instructions (HPGL).
// 0 = never. Parsed from --fault KIND=N[:CODE] by parse_fault().
struct Faults {
  size_t drop_at_line = 0;      // close the link after this many lines arrived (cable pulled)
  size_t stall_at_line = 0;     // stop reading and answering after this many lines (frozen controller)
  size_t freeze_at_line = 0;    // grbl: motion stops for good after this line, status queries still answered
  size_t garbage_at_line = 0;   // answer this line with line noise instead of the normal reply
  size_t error_at_line = 0;     // answer this line with an error (grbl error:CODE, HPGL device error)
  int error_code = 22;
  size_t alarm_at_line = 0;     // grbl: raise ALARM:CODE at this line
  int alarm_code = 1;
};

// "drop-at-line=40", "error-at-line=3:20", "alarm-at-line=10:1", "stall-at-line=5", "garbage-at-line=7".
bool parse_fault(const std::string& text, Faults& faults, std::string& error);

class ByteDevice {
 public:
  virtual ~ByteDevice() = default;
  // A byte arrived off the wire at now_s (seconds on the loop's clock).
  virtual void receive(char byte, double now_s) = 0;
  // Runs the machine up to now_s (motion, line processing, timers).
  virtual void advance(double now_s) = 0;
  // Bytes the machine wants to send since the last call.
  virtual std::string take_output() = 0;
  // The next time advance() has work to do; infinity when waiting for input only.
  virtual double next_event_s() const { return std::numeric_limits<double>::infinity(); }
  // Program lines / instructions received so far (the unit of Faults).
  virtual size_t lines_received() const = 0;
  // Writes what was received and the device's statistics into `dir`.
  virtual void write_record(const std::filesystem::path& dir) const = 0;
};

}  // namespace lastcut::drivers::sim
