// The option table and its checks, shared by the daemon's TOML reader and `lastcut send`.
#include "drivers/cutter_settings.hpp"

#include <sstream>
#include <type_traits>

namespace lastcut::drivers {
namespace {

using S = CutterSettings;

// One "$N=value" line: anything else would be streamed to the machine as a command.
std::string check_grbl_setting(const std::string& setting) {
  const auto equals = setting.find('=');
  if (setting.size() < 4 || setting[0] != '$' || equals == std::string::npos || equals < 2 ||
      setting.find_first_not_of("0123456789", 1) != equals || equals + 1 == setting.size()) {
    return "\"" + setting + "\" is not a grbl setting line like \"$110=5000\"";
  }
  return "";
}

std::string outside(double value, double min, double max) {
  std::ostringstream out;
  out << value << " is outside " << min << " .. " << max;
  return out.str();
}

std::string not_one_of(const std::string& value, const std::vector<std::string_view>& choices) {
  std::string text = "\"" + value + "\" is not one of ";
  for (std::size_t i = 0; i < choices.size(); ++i) {
    text += i ? ", " : "";
    text += choices[i].empty() ? "\"\"" : std::string(choices[i]);
  }
  return text;
}

}  // namespace

const std::vector<CutterOption>& cutter_options() {
  using K = OptionKind;
  static const std::vector<CutterOption> options{
      {"protocol", "--protocol", "grbl | hpgl | modbus (--modbus implies modbus)", K::Choice, &S::protocol, 0, 0,
       {"grbl", "hpgl", "modbus"}},
      {"port", "--port", "serial port, usb:VID:PID[:SERIAL], /dev/serial/by-id/..., tcp://HOST:PORT or a pty", K::Text,
       &S::port},
      {"modbus", "--modbus", "PLC-driven cutter: tcp://HOST:PORT or rtu:DEVICE[,BAUD[,8N1]]", K::Text, &S::modbus},
      {"baud", "--baud", "serial speed", K::Integer, &S::baud, 300, 4000000},
      {"data_bits", "--data-bits", "serial data bits", K::Integer, &S::data_bits, 5, 8},
      {"parity", "--parity", "serial parity: N | E | O", K::Choice, &S::parity, 0, 0, {"N", "E", "O"}},
      {"stop_bits", "--stop-bits", "serial stop bits", K::Integer, &S::stop_bits, 1, 2},
      {"flow", "--flow", "flow control: none | xonxoff | rtscts", K::Choice, &S::flow, 0, 0,
       {"none", "xonxoff", "rtscts"}},
      {"timeout_s", "--timeout", "seconds of silence before the job is declared lost", K::Number, &S::timeout_s, 0.1,
       3600},
      {"harmless_grbl_errors", "--harmless-errors", "grbl: error:N codes that do not stop the job (comma-separated)",
       K::Integers, &S::harmless_grbl_errors, 1, 255},
      {"grbl_streaming", "--streaming", "grbl: counting (character counting) | send-wait (one line at a time)",
       K::Choice, &S::grbl_streaming, 0, 0, {"counting", "send-wait"}},
      {"grbl_unlock", "--unlock", "grbl in alarm: never (refuse) | unlock (send $X first)", K::Choice, &S::grbl_unlock,
       0, 0, {"never", "unlock"}},
      {"grbl_rx_buffer_bytes", "--rx-buffer", "grbl: receive buffer bytes (0: ask the machine with $I)", K::Integer,
       &S::grbl_rx_buffer_bytes, 0, 65536},
      {"grbl_settings", "--grbl-setting", "grbl: \"$N=value\" line sent before the job (repeat or comma-separate)",
       K::Texts, &S::grbl_settings, 0, 0, {}, check_grbl_setting},
      {"status_poll_s", "--status-poll", "grbl: seconds between '?' status queries while streaming", K::Number,
       &S::status_poll_s, 0.01, 60},
      {"grbl_stall_s", "--stall-timeout",
       "grbl: seconds the machine may answer without moving or acknowledging a line before the job is stopped as "
       "stalled (0: never)",
       K::Number, &S::grbl_stall_s, 0, 86400},
      {"hpgl_handshake", "--handshake", "hpgl: \"\" follows --flow | escb (ESC.B buffer-space handshake)", K::Choice,
       &S::hpgl_handshake, 0, 0, {"", "escb"}},
      {"hpgl_status_queries", "--status-queries,!--no-status-queries",
       "hpgl: the device answers ESC.O / ESC.E / OA (--no-status-queries: it never does)", K::Switch,
       &S::hpgl_status_queries},
      {"modbus_map", "--map", "Modbus register map TOML (default: built-in map)", K::Text, &S::modbus_map},
      {"modbus_unit_id", "--unit-id", "Modbus unit (slave) id", K::Integer, &S::modbus_unit_id, 0, 247},
  };
  return options;
}

std::string set_cutter_option(CutterSettings& settings, const CutterOption& option, const OptionValue& value) {
  switch (option.kind) {
    case OptionKind::Text:
    case OptionKind::Choice: {
      const std::string& text = std::get<std::string>(value);
      if (option.kind == OptionKind::Choice) {
        bool known = false;
        for (std::string_view choice : option.choices) known = known || choice == text;
        if (!known) return not_one_of(text, option.choices);
      }
      if (auto* field = std::get_if<char S::*>(&option.field)) settings.*(*field) = text.empty() ? '\0' : text[0];
      else settings.*std::get<std::string S::*>(option.field) = text;
      return "";
    }
    case OptionKind::Integer: {
      const long long v = std::get<long long>(value);
      if (v < option.min || v > option.max) return outside(static_cast<double>(v), option.min, option.max);
      settings.*std::get<int S::*>(option.field) = static_cast<int>(v);
      return "";
    }
    case OptionKind::Number: {
      const double v = std::get<double>(value);
      if (!(v >= option.min && v <= option.max)) return outside(v, option.min, option.max);
      settings.*std::get<double S::*>(option.field) = v;
      return "";
    }
    case OptionKind::Switch:
      settings.*std::get<bool S::*>(option.field) = std::get<bool>(value);
      return "";
    case OptionKind::Integers: {
      std::vector<int> read;
      for (long long v : std::get<std::vector<long long>>(value)) {
        if (v < option.min || v > option.max) {
          std::ostringstream out;
          out << "each entry must be a whole number in " << option.min << " .. " << option.max;
          return out.str();
        }
        read.push_back(static_cast<int>(v));
      }
      settings.*std::get<std::vector<int> S::*>(option.field) = std::move(read);
      return "";
    }
    case OptionKind::Texts: {
      const auto& texts = std::get<std::vector<std::string>>(value);
      for (const std::string& text : texts) {
        if (std::string problem = option.check_entry ? option.check_entry(text) : ""; !problem.empty()) return problem;
      }
      settings.*std::get<std::vector<std::string> S::*>(option.field) = texts;
      return "";
    }
  }
  return "unknown option kind";
}

std::string option_text(const CutterSettings& settings, const CutterOption& option) {
  std::ostringstream out;
  std::visit(
      [&](auto field) {
        const auto& value = settings.*field;
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, bool>) {
          out << (value ? "true" : "false");
        } else if constexpr (std::is_same_v<T, std::vector<int>> || std::is_same_v<T, std::vector<std::string>>) {
          for (std::size_t i = 0; i < value.size(); ++i) out << (i ? "," : "") << value[i];
        } else {
          out << value;
        }
      },
      option.field);
  return out.str();
}

}  // namespace lastcut::drivers
