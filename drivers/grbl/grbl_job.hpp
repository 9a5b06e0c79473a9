#pragma once
// Streaming one G-code job to grbl with character counting (or send-and-wait), following the
// grbl 1.1 "Streaming Protocol: Character-Counting" description: keep the sum of the lengths of
// unacknowledged lines (each with its '\n') at or below the controller's RX buffer, pop one
// line per `ok` / `error:N`. The job is Done only when every line is acknowledged AND two
// consecutive status reports after the last acknowledgement say Idle (one report can race
// grbl's automatic cycle start of the last planner block). A machine that keeps answering but
// neither moves nor takes a line for `grbl_stall_s` is stopped (feed hold, soft reset) and the job
// reported Interrupted, never resent (motion_watch.hpp).
#include <atomic>
#include <string>
#include <vector>

#include "drivers/cutter.hpp"
#include "drivers/transport/transport.hpp"

namespace lastcut::drivers::grbl {

// The lines of a G-code program as they go on the wire: line endings normalised to "\n",
// whitespace-only lines dropped (grbl would only answer `ok`), everything else byte-exact.
std::vector<std::string> program_lines(const std::string& program);

SendResult run_grbl_job(Transport& link, const CutterConfig& config, const std::string& program,
                        const ProgressCallback& progress, const std::atomic<bool>& cancel);

ProbeResult probe_grbl(Transport& link, const CutterConfig& config);

}  // namespace lastcut::drivers::grbl
