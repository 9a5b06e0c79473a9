#include "daemon/watch/hot_folder.hpp"

#include <cerrno>
#include <cstring>
#include <sys/inotify.h>
#include <sys/statfs.h>
#include <unistd.h>

#include <spdlog/spdlog.h>

#include "daemon/job/job_ticket.hpp"
#include "daemon/watch/file_kind.hpp"
#include "daemon/watch/scan_completeness.hpp"

namespace lastcut::daemon {
namespace {

// statfs(2) f_type values of file systems where inotify does not see other machines' writes.
std::string network_file_system(const std::filesystem::path& folder) {
  struct statfs info {};
  if (::statfs(folder.c_str(), &info) != 0) return {};
  switch (static_cast<unsigned long>(info.f_type)) {
    case 0x6969UL: return "nfs";
    case 0x517BUL: return "smb";
    case 0xFF534D42UL: return "cifs";
    case 0xFE534D42UL: return "smb2";
    case 0x65735546UL: return "fuse";
    case 0x01021997UL: return "9p";
    default: return {};
  }
}

std::chrono::milliseconds to_ms(double seconds) {
  return std::chrono::milliseconds(static_cast<long long>(seconds * 1000.0));
}

}  // namespace

HotFolder::HotFolder(std::filesystem::path folder, WatchConfig config, HotFolderContent content)
    : folder_(std::move(folder)), config_(config), content_(content) {}

HotFolder::~HotFolder() {
  if (inotify_fd_ >= 0) ::close(inotify_fd_);
}

Status HotFolder::start() {
  std::error_code error;
  std::filesystem::create_directories(folder_, error);
  if (error) return Status::failure("cannot create watch folder " + folder_.string() + ": " + error.message());
  const std::string network = network_file_system(folder_);
  polling_ = config_.mode == WatchMode::Poll || (config_.mode == WatchMode::Auto && !network.empty());
  if (polling_) {
    mode_description_ = fmt::format("polling every {:g} s", config_.poll_interval_s) +
                        (network.empty() ? "" : " (network share: " + network + ")");
    return Status::success();
  }
  inotify_fd_ = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (inotify_fd_ < 0) return Status::failure(std::string("cannot start inotify: ") + std::strerror(errno));
  if (::inotify_add_watch(inotify_fd_, folder_.c_str(), IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_MODIFY) < 0) {
    return Status::failure("cannot watch " + folder_.string() + ": " + std::strerror(errno));
  }
  mode_description_ = fmt::format("inotify, full rescan every {:g} s", config_.rescan_interval_s);
  return Status::success();
}

void HotFolder::read_events() {
  if (inotify_fd_ < 0) return;
  alignas(struct inotify_event) char buffer[16384];
  const auto now = Clock::now();
  for (;;) {
    const ssize_t got = ::read(inotify_fd_, buffer, sizeof buffer);
    if (got <= 0) return;  // EAGAIN: drained
    for (char* at = buffer; at < buffer + got;) {
      const auto* event = reinterpret_cast<const struct inotify_event*>(at);
      if (event->mask & IN_Q_OVERFLOW) {
        ++overflow_count_;
        rescan_needed_ = true;
        spdlog::warn("watch folder: the kernel dropped file events (queue overflow); listing the folder again");
      } else if (event->len > 0) {
        note(event->name, now);
      }
      at += sizeof(struct inotify_event) + event->len;
    }
  }
}

bool HotFolder::acceptable_entry(const std::filesystem::path& path) {
  const std::string name = path.filename().string();
  const FileKind kind = content_ == HotFolderContent::Hides ? classify_hide_file_name(name) : classify_file_name(name);
  if (kind == FileKind::Temporary || kind == FileKind::Sidecar) return false;
  std::error_code error;
  const auto status = std::filesystem::symlink_status(path, error);
  if (error) return false;  // vanished meanwhile
  std::string refusal;
  if (std::filesystem::is_symlink(status)) refusal = "is a symbolic link (only real files are taken)";
  else if (!std::filesystem::is_regular_file(status)) refusal = "is not a regular file";
  else if (kind == FileKind::Unsupported)
    refusal = content_ == HotFolderContent::Hides ? "is not a hide file (.dxf or .json); left in place"
                                                  : "is not a scan (.stl, .obj, .ply or .off); left in place";
  if (refusal.empty()) return true;
  if (reported_.insert(name).second) spdlog::warn("watch folder: {} {}", name, refusal);
  return false;
}

void HotFolder::note(const std::string& file_name, Clock::time_point now) {
  auto [it, inserted] = candidates_.try_emplace(file_name);
  if (inserted) {
    it->second.next_check = now;
    it->second.unchanged_since = now;
  }
}

void HotFolder::rescan(Clock::time_point now) {
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder_, error), end; !error && it != end; it.increment(error)) {
    note(it->path().filename().string(), now);
  }
  if (error) spdlog::error("watch folder {}: cannot be listed: {}", folder_.string(), error.message());
  rescan_needed_ = false;
  next_rescan_ = now + to_ms(polling_ ? config_.poll_interval_s : config_.rescan_interval_s);
}

std::vector<ReadyScan> HotFolder::collect_ready(Clock::time_point now) {
  if (rescan_needed_ || now >= next_rescan_) rescan(now);
  std::vector<ReadyScan> ready;
  for (auto it = candidates_.begin(); it != candidates_.end();) {
    const std::filesystem::path path = folder_ / it->first;
    Candidate& candidate = it->second;
    if (!acceptable_entry(path)) {
      it = candidates_.erase(it);
      continue;
    }
    if (now < candidate.next_check) {
      ++it;
      continue;
    }
    candidate.next_check = now + to_ms(config_.stable_interval_s);
    std::error_code error;
    const auto size = std::filesystem::file_size(path, error);
    const auto mtime = error ? std::filesystem::file_time_type{} : std::filesystem::last_write_time(path, error);
    if (error) {
      it = candidates_.erase(it);  // gone (renamed away, deleted)
      continue;
    }
    if (size != candidate.size || mtime != candidate.mtime) {
      candidate.size = size;
      candidate.mtime = mtime;
      candidate.unchanged_checks = 0;
      candidate.unchanged_since = now;
      ++it;
      continue;
    }
    if (++candidate.unchanged_checks < config_.stable_checks) {
      ++it;
      continue;
    }
    ReadyScan scan = content_ == HotFolderContent::Hides ? ReadyScan{path, hide_sidecar(path), {}}
                                                         : ReadyScan{path, find_sidecar(path), scan_incompleteness(path)};
    if (!scan.incompleteness.empty() && now - candidate.unchanged_since < to_ms(config_.incomplete_grace_s)) {
      ++it;  // maybe the uploader only paused
      continue;
    }
    ready.push_back(std::move(scan));
    ++it;
  }
  return ready;
}

void HotFolder::forget(const std::string& file_name) { candidates_.erase(file_name); }

}  // namespace lastcut::daemon
