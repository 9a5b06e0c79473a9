#pragma once
// CutterSettings: how to reach one cutter and how to talk to it. The daemon reads it from a
// [cutters.NAME] table, `lastcut send` from its flags; both go through cutter_options() and
// set_cutter_option(), so every option is reachable from both and checked with the same words.
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace lastcut::drivers {

struct CutterSettings {
  std::string protocol;          // "grbl" | "hpgl" | "modbus"
  std::string port;              // /dev/ttyUSB0, /dev/serial/by-id/..., usb:VID:PID[:SERIAL], tcp://host:port, a pty path
  std::string modbus;            // tcp://127.0.0.1:1502 or rtu:/dev/ttyUSB1[,19200[,8N1]]
  int baud = 115200;
  int data_bits = 8;
  char parity = 'N';             // 'N' | 'E' | 'O'
  int stop_bits = 1;
  std::string flow = "none";     // "none" | "xonxoff" | "rtscts"
  double timeout_s = 10;         // longest silence from the device before the job is declared lost
  // grbl
  std::vector<int> harmless_grbl_errors;  // error:N codes that do not stop the job (default: none)
  std::string grbl_streaming = "counting";  // "counting" (character counting) | "send-wait" (one line at a time)
  std::string grbl_unlock = "never";        // "never": refuse a machine in alarm | "unlock": send $X first
  int grbl_rx_buffer_bytes = 0;             // 0: ask the machine ($I [OPT:...]), else force this size
  std::vector<std::string> grbl_settings;   // "$110=5000" lines sent one at a time before the job
  double status_poll_s = 0.2;               // '?' status query period while streaming
  double grbl_stall_s = 60;                 // Run/Idle without moving or acknowledging a line this long: stalled (0: off)
  // hpgl
  std::string hpgl_handshake = "";          // "" = follow `flow`; "escb" = ESC.B buffer-space handshake
  bool hpgl_status_queries = true;          // the device answers ESC.O / ESC.E / OA (most HP-compatible cutters do)
  // modbus
  std::string modbus_map;                   // register map TOML; empty = built-in default (config/modbus-register-map.toml)
  int modbus_unit_id = 1;
};

// The type a front door hands over: TOML and the command line each convert to it, then
// set_cutter_option() checks the value.
enum class OptionKind { Text, Choice, Integer, Number, Switch, Integers, Texts };
using OptionValue = std::variant<std::string, long long, double, bool, std::vector<long long>, std::vector<std::string>>;

struct CutterOption {
  using Field = std::variant<std::string CutterSettings::*, char CutterSettings::*, int CutterSettings::*,
                             double CutterSettings::*, bool CutterSettings::*, std::vector<int> CutterSettings::*,
                             std::vector<std::string> CutterSettings::*>;
  std::string_view key;   // TOML key in [cutters.NAME]
  std::string_view flag;  // `lastcut send` flag(s) in CLI11 spelling ("--parity"; "--status-queries,!--no-status-queries")
  std::string_view help;  // one line for --help
  OptionKind kind;
  Field field;
  double min = 0, max = 0;                // Integer, Number, Integers: allowed range
  std::vector<std::string_view> choices;  // Choice: allowed values
  std::string (*check_entry)(const std::string&) = nullptr;  // Texts: "" or why one entry is refused
};

// Every option of CutterSettings, in the order of the struct.
const std::vector<CutterOption>& cutter_options();

// Checks `value` (of the option's kind) and stores it; "" when stored, else one line without
// the key or flag ("\"X\" is not one of N, E, O", "3 is outside 1 .. 2").
std::string set_cutter_option(CutterSettings& settings, const CutterOption& option, const OptionValue& value);

// The option's current value as it is written in TOML or on the command line (for --help defaults).
std::string option_text(const CutterSettings& settings, const CutterOption& option);

}  // namespace lastcut::drivers
