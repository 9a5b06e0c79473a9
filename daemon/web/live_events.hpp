#pragma once
// LiveEvents: the StatusObserver behind the operator page's live stream (/api/events). The
// station's threads hand it job and cutter changes; each becomes one numbered Server-Sent Event
// kept in a short ring. A page follows the ring from the number it last saw, so memory stays
// bounded however many pages watch and however slow they read: a page that fell behind the ring
// is told to reload the overview ("resync") instead of being queued for. The newest state of
// each cutter is kept too, for a page that just opened.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "daemon/job/status_observer.hpp"

namespace lastcut::daemon {

nlohmann::json to_json(const JobEvent& event);
nlohmann::json to_json(const CutterStatus& status);

class LiveEvents : public StatusObserver {
 public:
  explicit LiveEvents(std::size_t ring_size = 1024) : ring_size_(ring_size) {}

  void job_changed(const JobEvent& event) override;
  void cutter_changed(const CutterStatus& status) override;
  void nesting_done(const NestingStatus& status) override;

  // What a watcher gets: the events numbered after the one it saw, each a complete SSE frame
  // ("id: N\nevent: job\ndata: {...}\n\n"); `resync` when some of them already left the ring.
  struct Frames {
    std::vector<std::string> frames;
    std::uint64_t last_id = 0;  // the number to ask after next time
    bool resync = false;
    bool closed = false;  // the daemon is stopping: end the stream
  };
  // Waits up to `wait` for an event after `after_id` (returns at once when there is one).
  Frames next(std::uint64_t after_id, std::chrono::milliseconds wait) const;
  std::uint64_t newest_id() const;
  // Each cutter's newest status, by name.
  nlohmann::json cutters() const;
  // Wakes every watcher and ends their streams (lastcutd stopping).
  void close();

 private:
  void publish(const std::string& kind, const nlohmann::json& data);

  const std::size_t ring_size_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::deque<std::pair<std::uint64_t, std::string>> ring_;
  std::uint64_t next_id_ = 1;
  std::map<std::string, nlohmann::json> cutters_;
  bool closed_ = false;
};

}  // namespace lastcut::daemon
