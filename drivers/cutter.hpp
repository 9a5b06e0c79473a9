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

#include "drivers/cutter_settings.hpp"

namespace lastcut::drivers {

// One job's view of a cutter: its settings plus the names that belong to this use of it.
struct CutterConfig : CutterSettings {
  std::string name;    // for messages: "cutter 'bench-1'"
  std::string job_id;  // written to the PLC's job-identity registers (<= 16 ASCII chars)
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
