#pragma once
// HpglCutter: a simulated HP-GL cutter/plotter with a small input buffer that drains at cutting
// speed. Flow control as on HP RS-232 devices: XON/XOFF (XOFF at 3/4 full, XON at 1/4) or the
// ESC.B buffer-space query; device-control instructions ESC.B, ESC.L, ESC.O, ESC.E, ESC.@, ESC.I,
// ESC.N, ESC.R, ESC.K are answered immediately, before the buffer, as on HP devices (HP-GL/2
// and HP RTL Reference Guide, "RS-232-C device control instructions"). Output instructions OA, OE,
// OI are answered when reached, i.e. after everything before them was cut. Records every cutting
// instruction byte-exact, buffer statistics, and the pen-down paths as SVG (40 plotter units/mm).
#include <string>
#include <vector>

#include "drivers/sim/byte_device.hpp"

namespace lastcut::drivers::sim {

struct HpglCutterOptions {
  std::string handshake = "xonxoff";  // "xonxoff" | "escb" | "none"
  int buffer_bytes = 1024;
  double speed_mm_per_s = 200;        // pen-down speed; pen-up moves at twice this
  double time_scale = 1.0;            // 0 = instant
  Faults faults;
};

class HpglCutter : public ByteDevice {
 public:
  explicit HpglCutter(HpglCutterOptions options) : options_(std::move(options)) {}

  void receive(char byte, double now_s) override;
  void advance(double now_s) override;
  std::string take_output() override;
  double next_event_s() const override;
  size_t lines_received() const override { return instructions_; }
  void write_record(const std::filesystem::path& dir) const override;

  const std::string& received_program() const { return received_; }
  size_t buffer_high_water() const { return high_water_; }
  size_t overflows() const { return overflows_; }

 private:
  struct Segment { double x0, y0, x1, y1; };
  void device_control(char command, const std::string& params);
  bool take_instruction(std::string& raw, std::string& mnemonic, std::vector<double>& params);
  void execute(const std::string& raw, const std::string& mnemonic, const std::vector<double>& params);
  void move_to(double x, double y);
  void answer(const std::string& text);
  void update_flow();

  HpglCutterOptions options_;
  std::string buffer_;
  std::string esc_;                 // device-control sequence being received
  std::string output_;
  std::string received_;
  double now_s_ = 0, busy_until_s_ = 0;
  bool halted_ = false, xoff_sent_ = false, garbage_next_ = false;
  bool awaiting_rest_ = false;  // the buffer holds only the start of an instruction
  bool pen_down_ = false, relative_ = false;
  double x_ = 0, y_ = 0;            // plotter units
  int device_error_ = 0, hpgl_error_ = 0;
  size_t instructions_ = 0, high_water_ = 0, overflows_ = 0, xoffs_ = 0;
  std::vector<Segment> cuts_;
};

}  // namespace lastcut::drivers::sim
