// Reading a cut file and sending it under the progress monitor's watch; see watched_send.hpp.
#include "daemon/station/watched_send.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

namespace lastcut::daemon {

std::optional<std::string> read_cut_program(const std::filesystem::path& cut_file) {
  // A batch with no cut-file name gives its folder here: refused with every other non-file.
  std::error_code ignored;  // a path that cannot be examined is refused like a missing file
  if (!std::filesystem::is_regular_file(cut_file, ignored)) return std::nullopt;
  std::ifstream in(cut_file, std::ios::binary);
  std::ostringstream program;
  program << in.rdbuf();
  if (!in || program.str().empty()) return std::nullopt;
  return program.str();
}

drivers::SendResult send_watched(ProgressMonitor& monitor, const std::string& worker, const std::string& task,
                                 const drivers::CutterConfig& config, const std::string& program,
                                 const drivers::ProgressCallback& on_progress, const std::atomic<bool>& cancel) {
  // Margin over the link's own timeout: the driver declares a silent cutter lost first, with a reason.
  constexpr double kWatchMargin_s = 30;
  monitor.begin(worker, task, config.timeout_s + kWatchMargin_s);
  const auto progress = [&](const drivers::SendProgress& step) {
    monitor.beat(worker);
    if (on_progress) on_progress(step);
  };
  drivers::SendResult result = drivers::send_job(config, program, progress, cancel);
  monitor.end(worker);
  return result;
}

}  // namespace lastcut::daemon
