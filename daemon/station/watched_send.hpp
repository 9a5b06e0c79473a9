#pragma once
// The sending half of the cutter worker (cutter_worker.hpp): the stored cut file read whole, and
// drivers::send_job under the progress monitor's watch.
#include <atomic>
#include <filesystem>
#include <optional>
#include <string>

#include "daemon/station/progress_monitor.hpp"
#include "drivers/cutter.hpp"

namespace lastcut::daemon {

// The cut file's bytes exactly as stored (what an operator inspects or replays with `lastcut send`
// is what the machine gets); nullopt when the file is missing, unreadable or empty, or not a regular
// file (a folder: what a batch without a cut-file name joins to, so callers need no check of their own).
std::optional<std::string> read_cut_program(const std::filesystem::path& cut_file);

// drivers::send_job, with `worker` busy on `task` in `monitor` meanwhile: every progress report is a
// heartbeat, and a cut that shows none for the link's timeout + 30 s counts as stuck (the systemd
// watchdog is then no longer fed). `on_progress` gets every report after the heartbeat.
drivers::SendResult send_watched(ProgressMonitor& monitor, const std::string& worker, const std::string& task,
                                 const drivers::CutterConfig& config, const std::string& program,
                                 const drivers::ProgressCallback& on_progress, const std::atomic<bool>& cancel);

}  // namespace lastcut::daemon
