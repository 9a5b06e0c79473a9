#pragma once
// The one entry point the daemon and the command line use to talk to a cutter:
// probe_cutter() before a job, send_job() to cut. No exceptions cross this API.
//
// Outcomes are chosen for leather that costs money: Done only when the machine reports it has
// FINISHED (grbl: every line acknowledged and status back to Idle; HPGL: the cutter answered
// an output query after the last instruction; Modbus: the PLC's status register says done).
// Interrupted means the cutter may have cut part of the job: lastcut never resends it on its own.
#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace lastcut::drivers {

struct CutterConfig {
  std::string name;              // for messages: "cutter 'bench-1'"
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
  // hpgl
  std::string hpgl_handshake = "";          // "" = follow `flow`; "escb" = ESC.B buffer-space handshake
  bool hpgl_status_queries = true;          // the device answers ESC.O / ESC.E / OA (most HP-compatible cutters do)
  // modbus
  std::string modbus_map;                   // register map TOML; empty = built-in default (config/modbus-register-map.toml)
  int modbus_unit_id = 1;
  std::string job_id;                       // written to the PLC's job-identity registers (<= 16 ASCII chars)
};

struct SendProgress {
  size_t bytes_sent = 0, bytes_total = 0;
  size_t lines_acked = 0, lines_total = 0;
  std::string device_state;      // "Run", "Hold:0", "receiving block 3/12", ...
};

enum class SendOutcome {
  Done,         // the machine reports the whole job finished
  Failed,       // nothing was sent to the machine: safe to retry
  Interrupted,  // the machine may have cut part of the job: never resend automatically
};

struct SendResult {
  SendOutcome outcome = SendOutcome::Failed;
  std::string reason;                    // one line for the operator ("grbl error:22 at line 3: Undefined feed rate...")
  std::vector<std::string> device_log;   // what the device said and what we did, in order
};

using ProgressCallback = std::function<void(const SendProgress&)>;

// Streams `program` (G-code, HPGL, or for Modbus the cutter's native program bytes) to the cutter.
// `progress` is called from this thread, at most every ~100 ms and at the end. Setting `cancel`
// stops the job: grbl gets feed hold then soft reset, HPGL stops sending, Modbus gets the abort command.
SendResult send_job(const CutterConfig& config, const std::string& program, const ProgressCallback& progress,
                    const std::atomic<bool>& cancel);

struct ProbeResult {
  bool ready = false;
  std::string state;    // "Idle", "Alarm", "ready", "not ready", ...
  std::string reason;   // why not ready, one line
};

// Opens the link, asks the machine for its state, closes. Never moves the machine.
ProbeResult probe_cutter(const CutterConfig& config);

std::string to_string(SendOutcome outcome);

}  // namespace lastcut::drivers
