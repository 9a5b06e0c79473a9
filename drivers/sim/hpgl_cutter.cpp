// HpglCutter: simulated HP-GL cutter (see hpgl_cutter.hpp).
#include "drivers/sim/hpgl_cutter.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace lastcut::drivers::sim {

namespace {

constexpr char kEsc = 0x1b, kXon = 0x11, kXoff = 0x13;
constexpr double kUnitsPerMm = 40.0;

bool is_param_char(char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == ',' || c == '-' || c == '+' || c == ' '; }
bool is_space(char c) { return c == ' ' || c == '\r' || c == '\n' || c == '\t'; }

}  // namespace

std::string HpglCutter::take_output() {
  std::string out;
  out.swap(output_);
  return out;
}

void HpglCutter::answer(const std::string& text) {
  if (garbage_next_) {
    garbage_next_ = false;
    output_ += "\x7f\xfe#?%\r";
    return;
  }
  output_ += text + "\r";
}

void HpglCutter::update_flow() {
  if (options_.handshake != "xonxoff") return;
  const size_t fill = buffer_.size(), capacity = static_cast<size_t>(options_.buffer_bytes);
  // While the buffer holds only the start of an instruction the flow stays open: holding XOFF then
  // would wait for bytes this plotter stopped itself, as a PD of many pairs can be longer than the
  // 25 % fill at which XON comes (the ledger test's cut files have PDs of 769 bytes). A real plotter
  // runs a PD's pairs as they arrive; one longer than the buffer still overflows here.
  if (!xoff_sent_ && !awaiting_rest_ && fill * 4 >= capacity * 3) {
    output_ += kXoff;
    xoff_sent_ = true;
    ++xoffs_;
  } else if (xoff_sent_ && (awaiting_rest_ || fill * 4 <= capacity)) {
    output_ += kXon;
    xoff_sent_ = false;
  }
}

void HpglCutter::receive(char byte, double now_s) {
  now_s_ = now_s;
  if (!esc_.empty() || byte == kEsc) {
    esc_ += byte;
    if (esc_.size() == 2 && byte != '.') {
      device_error_ = 11;  // invalid byte after ESC
      esc_.clear();
    } else if (esc_.size() >= 3) {
      const char command = esc_[2];
      const bool takes_params = command == '@' || command == 'H' || command == 'I' || command == 'M' || command == 'N';
      if (!takes_params || byte == ':' || esc_.size() > 40) {
        device_control(command, takes_params ? esc_.substr(3) : "");
        esc_.clear();
      }
    }
    return;
  }
  if (buffer_.size() >= static_cast<size_t>(options_.buffer_bytes)) {
    ++overflows_;
    device_error_ = 16;  // input buffer overflowed: the byte is lost
    return;
  }
  buffer_ += byte;
  high_water_ = std::max(high_water_, buffer_.size());
  update_flow();
}

void HpglCutter::device_control(char command, const std::string& /*params*/) {
  const size_t free_bytes = static_cast<size_t>(options_.buffer_bytes) - buffer_.size();
  switch (command) {
    case 'B': answer(std::to_string(free_bytes)); break;
    case 'L': answer(std::to_string(options_.buffer_bytes)); break;
    case 'O': {
      // Extended status as this simulated profile reports it: 8 = buffer empty and idle, 32 = halted by an error.
      int status = 0;
      if (buffer_.empty() && now_s_ >= busy_until_s_) status |= 8;
      if (halted_) status |= 32;
      answer(std::to_string(status));
      break;
    }
    case 'E':
      answer(std::to_string(device_error_));
      device_error_ = 0;
      break;
    case 'R': case 'K':
      buffer_.clear();
      halted_ = false;
      update_flow();
      break;
    case '@': case 'H': case 'I': case 'M': case 'N': case 'J': case 'Y': case 'Z': case '(': case ')':
      break;
    default: device_error_ = 12; break;
  }
}

bool HpglCutter::take_instruction(std::string& raw, std::string& mnemonic, std::vector<double>& params) {
  size_t i = 0;
  while (i < buffer_.size() && (is_space(buffer_[i]) || buffer_[i] == ';')) ++i;
  if (i + 2 > buffer_.size()) return false;
  mnemonic = {static_cast<char>(std::toupper(static_cast<unsigned char>(buffer_[i]))),
              static_cast<char>(std::toupper(static_cast<unsigned char>(buffer_[i + 1])))};
  size_t j = i + 2;
  if (mnemonic == "LB") {
    const auto etx = buffer_.find('\x03', j);
    if (etx == std::string::npos) return false;
    j = etx + 1;
  } else {
    while (j < buffer_.size() && is_param_char(buffer_[j])) ++j;
    if (j >= buffer_.size()) return false;  // the terminator has not arrived yet
    const std::string text = buffer_.substr(i + 2, j - i - 2);
    const char* p = text.c_str();
    while (*p) {
      char* end = nullptr;
      const double v = std::strtod(p, &end);
      if (end == p) { ++p; continue; }
      params.push_back(v);
      p = end;
    }
  }
  if (j < buffer_.size() && buffer_[j] == ';') ++j;
  // Trailing whitespace belongs to this instruction, so the record keeps the program's line breaks.
  while (j < buffer_.size() && is_space(buffer_[j])) ++j;
  raw = buffer_.substr(0, j);
  buffer_.erase(0, j);
  update_flow();
  return true;
}

void HpglCutter::move_to(double x, double y) {
  const double length_mm = std::hypot(x - x_, y - y_) / kUnitsPerMm;
  const double speed = pen_down_ ? options_.speed_mm_per_s : 2 * options_.speed_mm_per_s;
  busy_until_s_ = std::max(busy_until_s_, now_s_) + length_mm / speed * options_.time_scale;
  if (pen_down_) cuts_.push_back({x_, y_, x, y});
  x_ = x, y_ = y;
}

void HpglCutter::execute(const std::string& raw, const std::string& mnemonic, const std::vector<double>& params) {
  if (mnemonic[0] == 'O') {  // output instructions are queries, not part of the cut
    received_ += raw.substr(0, raw.find_first_not_of(" \r\n\t;"));  // keep the program's own line break
    if (mnemonic == "OA") answer(std::to_string(static_cast<long>(x_)) + "," + std::to_string(static_cast<long>(y_)) + "," + (pen_down_ ? "1" : "0"));
    else if (mnemonic == "OE") { answer(std::to_string(hpgl_error_)); hpgl_error_ = 0; }
    else if (mnemonic == "OI") answer("lastcut-sim");
    else answer("0");
    return;
  }
  received_ += raw;
  ++instructions_;
  const Faults& f = options_.faults;
  if (f.error_at_line == instructions_) {
    device_error_ = f.error_code >= 10 && f.error_code <= 16 ? f.error_code : 13;
    halted_ = true;
    return;
  }
  if (f.garbage_at_line == instructions_) garbage_next_ = true;
  if (mnemonic == "IN") { pen_down_ = false; relative_ = false; x_ = y_ = 0; return; }
  if (mnemonic == "PU" || mnemonic == "PD" || mnemonic == "PA" || mnemonic == "PR") {
    if (mnemonic == "PU") pen_down_ = false;
    if (mnemonic == "PD") pen_down_ = true;
    if (mnemonic == "PA") relative_ = false;
    if (mnemonic == "PR") relative_ = true;
    if (params.size() % 2 != 0) { hpgl_error_ = 2; return; }
    for (size_t k = 0; k + 1 < params.size(); k += 2) {
      move_to(relative_ ? x_ + params[k] : params[k], relative_ ? y_ + params[k + 1] : params[k + 1]);
    }
    return;
  }
  static const std::string kKnown = "SP VS LT SC IP IW DF CI LB SI DI FS VS PT ";
  if (kKnown.find(mnemonic + " ") == std::string::npos) hpgl_error_ = 1;
}

double HpglCutter::next_event_s() const {
  if (halted_ || buffer_.empty()) return ByteDevice::next_event_s();
  return std::max(busy_until_s_, now_s_);
}

void HpglCutter::advance(double now_s) {
  now_s_ = now_s;
  while (!halted_ && now_s >= busy_until_s_) {
    std::string raw, mnemonic;
    std::vector<double> params;
    if (!take_instruction(raw, mnemonic, params)) {
      awaiting_rest_ = !buffer_.empty();
      update_flow();
      break;
    }
    awaiting_rest_ = false;
    execute(raw, mnemonic, params);
  }
}

void HpglCutter::write_record(const std::filesystem::path& dir) const {
  std::ofstream(dir / "hpgl-received.hpgl", std::ios::binary) << received_;
  std::ofstream(dir / "hpgl-stats.json") << "{\"buffer_bytes\": " << options_.buffer_bytes << ", \"buffer_high_water_bytes\": "
                                         << high_water_ << ", \"overflows\": " << overflows_ << ", \"xoff_sent\": " << xoffs_
                                         << ", \"instructions\": " << instructions_ << ", \"halted\": " << (halted_ ? "true" : "false")
                                         << "}\n";
  double max_x = 1, max_y = 1;
  for (const auto& s : cuts_) max_x = std::max({max_x, s.x0, s.x1}), max_y = std::max({max_y, s.y0, s.y1});
  std::ofstream svg(dir / "cut.svg");
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << max_x / kUnitsPerMm << "mm\" height=\"" << max_y / kUnitsPerMm
      << "mm\" viewBox=\"0 0 " << max_x / kUnitsPerMm << " " << max_y / kUnitsPerMm << "\">\n"
      << "<g fill=\"none\" stroke=\"black\" stroke-width=\"0.2\" transform=\"translate(0 " << max_y / kUnitsPerMm
      << ") scale(1 -1)\">\n";
  for (const auto& s : cuts_) {
    svg << "<line x1=\"" << s.x0 / kUnitsPerMm << "\" y1=\"" << s.y0 / kUnitsPerMm << "\" x2=\"" << s.x1 / kUnitsPerMm
        << "\" y2=\"" << s.y1 / kUnitsPerMm << "\"/>\n";
  }
  svg << "</g>\n</svg>\n";
}

}  // namespace lastcut::drivers::sim
