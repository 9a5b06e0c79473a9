#pragma once
// Streaming an HP-GL program to a cutter or plotter with the flow control its profile names:
// XON/XOFF (read from the line by us, so a cutter that holds XOFF too long is reported),
// RTS/CTS (in the serial driver), none, or the ESC.B buffer-space handshake (ask how many bytes
// fit, send that many). When the device answers queries (hpgl_status_queries), ESC.O checks it
// is ready before the job, ESC.E is polled for device errors while streaming, and the job is
// Done only when an OA (output actual position) placed after the last instruction is answered:
// HP-GL devices execute instructions in order, so the answer means everything before was cut.
#include <atomic>
#include <string>

#include "drivers/cutter.hpp"
#include "drivers/transport/transport.hpp"

namespace lastcut::drivers::hpgl {

SendResult run_hpgl_job(Transport& link, const CutterConfig& config, const std::string& program,
                        const ProgressCallback& progress, const std::atomic<bool>& cancel);

ProbeResult probe_hpgl(Transport& link, const CutterConfig& config);

}  // namespace lastcut::drivers::hpgl
