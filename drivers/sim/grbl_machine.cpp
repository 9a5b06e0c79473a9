// GrblMachine: simulated grbl 1.1 (see grbl_machine.hpp).
#include "drivers/sim/grbl_machine.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>

namespace lastcut::drivers::sim {

namespace {

constexpr int kLineBufferBytes = 80;      // grbl's LINE_BUFFER_SIZE
constexpr double kRapidMmPerMin = 6000;

std::string format3(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", v);
  return buffer;
}

// Strips comments "(...)" and "; ...", whitespace, and upper-cases, as grbl's line reader does.
std::string normalise(const std::string& line) {
  std::string out;
  bool in_paren = false;
  for (char c : line) {
    if (in_paren) {
      if (c == ')') in_paren = false;
      continue;
    }
    if (c == '(') { in_paren = true; continue; }
    if (c == ';') break;
    if (c == ' ' || c == '\t' || c == '\r') continue;
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

}  // namespace

GrblMachine::GrblMachine(GrblMachineOptions options) : options_(std::move(options)) {
  settings_ = {{0, "10"}, {1, "25"}, {10, "1"}, {20, "0"}, {21, "0"}, {22, "0"}, {110, "5000.000"},
               {111, "5000.000"}, {112, "500.000"}, {120, "100.000"}, {121, "100.000"}, {122, "100.000"}};
}

void GrblMachine::power_on(double now_s) {
  now_s_ = now_s;
  output_ += "\r\nGrbl 1.1h ['$' for help]\r\n";
}

std::string GrblMachine::state_name() const {
  switch (state_) {
    case State::Idle: return "Idle";
    case State::Run: return "Run";
    case State::Hold1: return "Hold:1";
    case State::Hold0: return "Hold:0";
    case State::Alarm: return "Alarm";
  }
  return "Idle";
}

std::string GrblMachine::take_output() {
  std::string out;
  out.swap(output_);
  return out;
}

void GrblMachine::receive(char byte, double now_s) {
  now_s_ = now_s;
  if (byte == '?' || byte == '!' || byte == '~' || byte == 0x18) {
    realtime(byte, now_s);
    return;
  }
  if (unanswered_bytes_ + 1 > static_cast<size_t>(options_.rx_buffer_bytes)) {
    ++rx_overflows_;  // the real serial ISR drops the byte; the line arrives corrupted
    return;
  }
  rx_ += byte;
  ++unanswered_bytes_;
  if (unanswered_bytes_ > rx_high_water_) rx_high_water_ = unanswered_bytes_;
}

void GrblMachine::realtime(char byte, double now_s) {
  switch (byte) {
    case '?': status_report(); break;
    case '!':
      if (state_ == State::Run) {
        block_left_s_ = std::max(0.0, block_end_s_ - now_s);
        state_ = State::Hold1;
        hold_done_s_ = now_s + options_.hold_decel_s;
      } else if (state_ == State::Idle) {
        block_left_s_ = 0;
        state_ = State::Hold0;
      }
      break;
    case '~':
      // grbl resumes only a completed hold; cycle start during deceleration is ignored.
      if (state_ == State::Hold0) {
        state_ = planner_.empty() ? State::Idle : State::Run;
        block_end_s_ = now_s + block_left_s_;
      }
      break;
    default: reset(now_s); break;
  }
}

void GrblMachine::reset(double now_s) {
  const bool moving = state_ == State::Run || state_ == State::Hold1;
  rx_.clear();
  unanswered_bytes_ = 0;
  planner_.clear();
  target_x_ = x_, target_y_ = y_, target_z_ = z_;
  if (moving) {
    reply("ALARM:3");
    ++alarms_raised_;
    state_ = State::Alarm;
  } else if (state_ != State::Alarm) {
    state_ = State::Idle;
  }
  power_on(now_s);
  if (state_ == State::Alarm) reply("[MSG:'$H'|'$X' to unlock]");
}

void GrblMachine::raise_alarm(int code) {
  reply("ALARM:" + std::to_string(code));
  reply("[MSG:Reset to continue]");
  ++alarms_raised_;
  state_ = State::Alarm;
  planner_.clear();
  rx_.clear();
  unanswered_bytes_ = 0;
}

void GrblMachine::status_report() {
  const size_t free_rx = static_cast<size_t>(options_.rx_buffer_bytes) - unanswered_bytes_;
  const int free_blocks = options_.planner_blocks - static_cast<int>(planner_.size());
  reply("<" + state_name() + "|MPos:" + format3(x_) + "," + format3(y_) + "," + format3(z_) +
        "|Bf:" + std::to_string(free_blocks) + "," + std::to_string(free_rx) + "|FS:" +
        std::to_string(static_cast<int>(feed_mm_per_min_)) + ",0>");
}

double GrblMachine::next_event_s() const {
  if (state_ == State::Hold1) return hold_done_s_;
  if (state_ == State::Run && !planner_.empty() && !motion_frozen_) return block_end_s_;
  if (rx_.find('\n') != std::string::npos && static_cast<int>(planner_.size()) < options_.planner_blocks) return now_s_;
  return ByteDevice::next_event_s();
}

void GrblMachine::advance(double now_s) {
  now_s_ = now_s;
  bool changed = true;
  while (changed) {
    changed = false;
    if (state_ == State::Hold1 && now_s >= hold_done_s_) {
      state_ = State::Hold0;
      changed = true;
    }
    if (state_ == State::Idle && !planner_.empty()) {
      state_ = State::Run;  // auto cycle start
      block_end_s_ = now_s + planner_.front().duration_s;
      changed = true;
    }
    while (state_ == State::Run && !planner_.empty() && now_s >= block_end_s_ && !motion_frozen_) {
      x_ = planner_.front().x, y_ = planner_.front().y, z_ = planner_.front().z;
      const double finished_at = block_end_s_;
      planner_.pop_front();
      if (!planner_.empty()) block_end_s_ = finished_at + planner_.front().duration_s;
      changed = true;
    }
    if (state_ == State::Run && planner_.empty()) {
      state_ = State::Idle;
      changed = true;
    }
    const auto newline = rx_.find('\n');
    if (newline != std::string::npos && static_cast<int>(planner_.size()) < options_.planner_blocks) {
      const std::string line = rx_.substr(0, newline);
      rx_.erase(0, newline + 1);
      unanswered_bytes_ -= newline + 1;
      process_line(line);
      changed = true;
    }
  }
}

void GrblMachine::process_line(const std::string& line) {
  const std::string body = normalise(line);
  if (!body.empty() && body[0] == '$') {
    process_system_command(body);
    return;
  }
  received_program_ += line + "\n";
  ++lines_received_;
  const Faults& f = options_.faults;
  if (f.alarm_at_line == lines_received_) {
    raise_alarm(f.alarm_code);
    return;
  }
  if (f.garbage_at_line == lines_received_) {
    output_ += std::string("\xff\xfe\x01\x7fok\x93\x02") + "\r\n";
    return;
  }
  if (f.freeze_at_line == lines_received_) motion_frozen_ = true;
  if (f.error_at_line == lines_received_) {
    ++errors_sent_;
    reply("error:" + std::to_string(f.error_code));
    return;
  }
  const int error = state_ == State::Alarm ? 9 : execute_gcode(body);
  if (error != 0) {
    ++errors_sent_;
    reply("error:" + std::to_string(error));
  } else {
    reply("ok");
  }
}

void GrblMachine::process_system_command(const std::string& body) {
  if (body == "$I") {
    reply("[VER:1.1h.20190825:lastcut-sim]");
    reply("[OPT:V," + std::to_string(options_.planner_blocks) + "," + std::to_string(options_.rx_buffer_bytes) + "]");
  } else if (body == "$X") {
    if (state_ == State::Alarm) {
      state_ = State::Idle;
      reply("[MSG:Caution: Unlocked]");
    }
  } else if (body == "$$") {
    for (const auto& [number, value] : settings_) reply("$" + std::to_string(number) + "=" + value);
  } else if (body == "$G") {
    reply("[GC:G" + std::to_string(motion_mode_) + " G54 G17 G21 " + (absolute_ ? "G90" : "G91") + " G94 M5 M9 T0 F" +
          std::to_string(static_cast<int>(feed_mm_per_min_)) + " S0]");
  } else if (body == "$H") {
    reply("error:5");
    return;
  } else if (body.size() > 3 && std::isdigit(static_cast<unsigned char>(body[1])) && body.find('=') != std::string::npos) {
    if (state_ != State::Idle && state_ != State::Alarm) {
      reply("error:8");
      return;
    }
    char* end = nullptr;
    const long number = std::strtol(body.c_str() + 1, &end, 10);
    if (*end != '=' || end[1] == '\0') {
      reply("error:3");
      return;
    }
    settings_[static_cast<int>(number)] = std::string(end + 1);
  } else {
    reply("error:3");
    return;
  }
  reply("ok");
}

int GrblMachine::execute_gcode(const std::string& body) {
  if (static_cast<int>(body.size()) >= kLineBufferBytes) return 11;
  static const std::set<double> kGCodes{0, 1, 2, 3, 4, 10, 17, 18, 19, 20, 21, 28, 30, 40, 43.1, 49, 53, 54, 55, 56, 57, 58, 59, 61, 80, 90, 91, 92, 93, 94};
  static const std::set<double> kMCodes{0, 1, 2, 3, 4, 5, 7, 8, 9, 30, 56};
  static const std::string kLetters = "FGIJKLMNPRSTXYZ";
  bool has_axis = false, dwell = false;
  double dwell_s = 0;
  double nx = target_x_, ny = target_y_, nz = target_z_;
  int motion = motion_mode_;
  bool absolute = absolute_;
  double feed = feed_mm_per_min_;
  size_t i = 0;
  while (i < body.size()) {
    const char letter = body[i++];
    if (letter < 'A' || letter > 'Z') return 1;
    // A G-code number is [+-]digits[.digits]; strtod would also take hex ("0X58" after "G"
    // once spaces are gone), exponents and "inf", which grbl does not.
    const size_t number_start = i;
    if (i < body.size() && (body[i] == '+' || body[i] == '-')) ++i;
    const size_t digits_start = i;
    while (i < body.size() && (std::isdigit(static_cast<unsigned char>(body[i])) || body[i] == '.')) ++i;
    if (i == digits_start) return 2;
    const std::string number_text = body.substr(number_start, i - number_start);
    char* end = nullptr;
    const double value = std::strtod(number_text.c_str(), &end);
    if (end != number_text.c_str() + number_text.size()) return 2;
    if (kLetters.find(letter) == std::string::npos) return 20;
    switch (letter) {
      case 'G':
        if (!kGCodes.count(value)) return 20;
        if (value == 0 || value == 1 || value == 2 || value == 3) motion = static_cast<int>(value);
        if (value == 4) dwell = true;
        if (value == 90) absolute = true;
        if (value == 91) absolute = false;
        break;
      case 'M':
        if (!kMCodes.count(value)) return 20;
        break;
      case 'F':
        if (value < 0) return 4;
        feed = value;
        break;
      case 'P': dwell_s = value; break;
      case 'X': nx = absolute ? value : nx + value; has_axis = true; break;
      case 'Y': ny = absolute ? value : ny + value; has_axis = true; break;
      case 'Z': nz = absolute ? value : nz + value; has_axis = true; break;
      default: break;
    }
  }
  if (has_axis && motion != 0 && feed <= 0) return 22;
  motion_mode_ = motion;
  absolute_ = absolute;
  feed_mm_per_min_ = feed;
  if (dwell) planner_.push_back({dwell_s * options_.time_scale, target_x_, target_y_, target_z_});
  if (has_axis) {
    const double distance = std::sqrt((nx - target_x_) * (nx - target_x_) + (ny - target_y_) * (ny - target_y_) +
                                      (nz - target_z_) * (nz - target_z_));
    const double rate = motion == 0 ? kRapidMmPerMin : feed;
    planner_.push_back({distance / rate * 60.0 * options_.time_scale, nx, ny, nz});
    target_x_ = nx, target_y_ = ny, target_z_ = nz;
  }
  return 0;
}

void GrblMachine::write_record(const std::filesystem::path& dir) const {
  std::ofstream(dir / "grbl-received.nc", std::ios::binary) << received_program_;
  std::ofstream stats(dir / "grbl-stats.json");
  stats << "{\"rx_buffer_bytes\": " << options_.rx_buffer_bytes << ", \"rx_high_water_bytes\": " << rx_high_water_
        << ", \"rx_overflows\": " << rx_overflows_ << ", \"lines\": " << lines_received_
        << ", \"errors_sent\": " << errors_sent_ << ", \"alarms\": " << alarms_raised_ << ", \"state\": \"" << state_name()
        << "\"}\n";
}

}  // namespace lastcut::drivers::sim
