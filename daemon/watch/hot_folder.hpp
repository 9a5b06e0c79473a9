#pragma once
// HotFolder: finds scans dropped into the watch folder and says when each one is complete.
// Events come from inotify (IN_CLOSE_WRITE, IN_MOVED_TO); a full listing runs at start, after
// IN_Q_OVERFLOW (events were lost) and every rescan interval as a safety net. On network
// shares (NFS, SMB/CIFS, FUSE: statfs magic) inotify misses remote writers, so the folder is
// listed every poll interval instead. A file is ready once its size and mtime stayed the same
// for `stable_checks` checks and it looks complete (scan_completeness.hpp); one that stays
// cut off past the grace time is handed over anyway with the reason, so it ends in failed/.
// Symlinks, folders and other non-regular entries are never taken (one log line each).
#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "daemon/config/daemon_config.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

// What a hot folder takes: scans (with NAME.job.toml sidecars, checked for completeness) or hide
// files (.dxf, .json, with NAME.toml sidecars; docs/hides.md).
enum class HotFolderContent { Scans, Hides };

struct ReadyScan {
  std::filesystem::path scan;
  std::filesystem::path sidecar;  // empty when none
  std::string incompleteness;     // non-empty: still cut off after the grace time
};

class HotFolder {
 public:
  using Clock = std::chrono::steady_clock;

  HotFolder(std::filesystem::path folder, WatchConfig config, HotFolderContent content = HotFolderContent::Scans);
  ~HotFolder();
  HotFolder(const HotFolder&) = delete;
  HotFolder& operator=(const HotFolder&) = delete;

  // Creates the folder if needed and starts watching.
  Status start();
  // "inotify" or "polling (nfs)"...: for the start-up log line.
  const std::string& mode_description() const { return mode_description_; }
  // The inotify descriptor to wait on, or -1 when polling.
  int event_fd() const { return inotify_fd_; }
  // Reads the pending inotify events without blocking.
  void read_events();
  // Rescans when due, re-checks candidates; returns the scans ready to be taken.
  std::vector<ReadyScan> collect_ready(Clock::time_point now);
  // The daemon took (or gave up on) this file: stop tracking it.
  void forget(const std::string& file_name);
  // Candidates being watched for completeness (for status and tests).
  std::size_t pending_count() const { return candidates_.size(); }
  // Events lost by the kernel since start (IN_Q_OVERFLOW count); each triggered a full rescan.
  int overflow_count() const { return overflow_count_; }

 private:
  struct Candidate {
    std::uintmax_t size = 0;
    std::filesystem::file_time_type mtime{};
    int unchanged_checks = 0;
    Clock::time_point next_check{};
    Clock::time_point unchanged_since{};
  };

  void rescan(Clock::time_point now);
  void note(const std::string& file_name, Clock::time_point now);
  bool acceptable_entry(const std::filesystem::path& path);

  std::filesystem::path folder_;
  WatchConfig config_;
  HotFolderContent content_;
  int inotify_fd_ = -1;
  bool polling_ = false;
  std::string mode_description_;
  bool rescan_needed_ = true;
  int overflow_count_ = 0;
  Clock::time_point next_rescan_{};
  std::map<std::string, Candidate> candidates_;
  std::set<std::string> reported_;  // names already logged as refused (log once, not every scan)
};

}  // namespace lastcut::daemon
