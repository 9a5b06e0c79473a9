#pragma once
// GrblMachine: a simulated grbl 1.1 controller for tests, benchmarks and dry runs.
// Models what a sender can get wrong: the 128-byte serial receive buffer (occupancy = bytes
// arrived and not yet answered, which is what character counting bounds; the high-water mark
// and overflows are recorded, and overflowing bytes are dropped as on the real chip), a
// 15-block planner with simulated motion time (x time_scale; 0 = instant), `error:N` for bad
// lines, alarms that lock G-code out (error:9), feed hold with a deceleration phase
// (Hold:1 -> Hold:0), cycle start, soft reset (ALARM:3 when reset in motion) and `$` commands.
// The freeze-at-line fault copies what the grbl 1.1h host simulator does when its stepper
// interrupt dies: "Run" forever at one position, the planner full, status still answered.
// Behaviour follows the grbl 1.1 interface documentation (gnea/grbl wiki).
#include <deque>
#include <map>
#include <string>

#include "drivers/sim/byte_device.hpp"

namespace lastcut::drivers::sim {

struct GrblMachineOptions {
  int rx_buffer_bytes = 128;
  int planner_blocks = 15;
  double time_scale = 1.0;      // simulated motion seconds per real motion second; 0 = instant
  double hold_decel_s = 0.1;    // time from '!' to Hold:0 while moving (real seconds)
  Faults faults;
};

class GrblMachine : public ByteDevice {
 public:
  explicit GrblMachine(GrblMachineOptions options);

  void power_on(double now_s);  // prints the banner, as grbl does after a reset
  void receive(char byte, double now_s) override;
  void advance(double now_s) override;
  std::string take_output() override;
  double next_event_s() const override;
  size_t lines_received() const override { return lines_received_; }
  void write_record(const std::filesystem::path& dir) const override;

  std::string state_name() const;       // "Idle", "Run", "Hold:0", "Hold:1", "Alarm"
  size_t rx_high_water_bytes() const { return rx_high_water_; }
  size_t rx_overflows() const { return rx_overflows_; }
  const std::string& received_program() const { return received_program_; }

 private:
  enum class State { Idle, Run, Hold1, Hold0, Alarm };
  struct Block { double duration_s; double x, y, z; };

  void process_line(const std::string& line);
  void process_system_command(const std::string& line);
  int execute_gcode(const std::string& line);  // 0 or a grbl error code
  void realtime(char byte, double now_s);
  void reset(double now_s);
  void raise_alarm(int code);
  void status_report();
  void reply(const std::string& line) { output_ += line + "\r\n"; }

  GrblMachineOptions options_;
  State state_ = State::Idle;
  double now_s_ = 0;
  std::string rx_;                // arrived bytes not yet parsed into a line
  size_t unanswered_bytes_ = 0;   // arrived bytes whose line has not been answered yet
  size_t rx_high_water_ = 0, rx_overflows_ = 0;
  std::deque<Block> planner_;
  double block_end_s_ = 0;        // when the front block finishes (Run)
  double block_left_s_ = 0;       // remaining time of the front block while held
  double hold_done_s_ = 0;
  double x_ = 0, y_ = 0, z_ = 0;  // machine position after the last finished block, mm
  double target_x_ = 0, target_y_ = 0, target_z_ = 0;
  int motion_mode_ = 0;           // 0 rapid, 1 linear, 2/3 arc
  double feed_mm_per_min_ = 0;
  bool absolute_ = true;
  std::map<int, std::string> settings_;
  std::string output_;
  std::string received_program_;  // program lines (not '$' commands), as received, '\n'-terminated
  size_t lines_received_ = 0;
  size_t errors_sent_ = 0, alarms_raised_ = 0;
  bool motion_frozen_ = false;    // freeze-at-line: the steppers stopped, the serial side lives on
};

}  // namespace lastcut::drivers::sim
