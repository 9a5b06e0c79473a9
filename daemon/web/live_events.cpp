// LiveEvents (live_events.hpp): the ring of numbered Server-Sent Events the operator page follows.
#include "daemon/web/live_events.hpp"

namespace lastcut::daemon {

nlohmann::json to_json(const JobEvent& event) {
  return {{"id", event.job_id},         {"scan", event.scan_name}, {"order", event.order},
          {"material", event.material}, {"cutter", event.cutter}, {"batch", event.batch_id},
          {"stage", std::string(to_string(event.stage))},          {"note", event.note},
          {"reason", event.reason},     {"at", event.at}};
}

nlohmann::json to_json(const CutterStatus& status) {
  return {{"cutter", status.cutter},         {"state", status.state},           {"batch", status.batch},
          {"reason", status.reason},         {"lines_sent", status.lines_sent}, {"lines_total", status.lines_total},
          {"bytes_sent", status.bytes_sent}, {"bytes_total", status.bytes_total}};
}

void LiveEvents::job_changed(const JobEvent& event) { publish("job", to_json(event)); }

void LiveEvents::cutter_changed(const CutterStatus& status) {
  const nlohmann::json data = to_json(status);
  {
    std::lock_guard lock(mutex_);
    cutters_[status.cutter] = data;
  }
  publish("cutter", data);
}

void LiveEvents::nesting_done(const NestingStatus& status) { publish("nesting", to_json(status)); }

void LiveEvents::publish(const std::string& kind, const nlohmann::json& data) {
  // When it was published (Unix ms), so a page can tell how late it arrived (docs/operator-page.md).
  nlohmann::json stamped = data;
  stamped["published_ms"] = std::chrono::duration_cast<std::chrono::milliseconds>(
                                std::chrono::system_clock::now().time_since_epoch()).count();
  // Formatted once here, not once per watcher. JSON never holds a raw newline, so one data line.
  const std::string payload = stamped.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  {
    std::lock_guard lock(mutex_);
    const std::uint64_t id = next_id_++;
    ring_.emplace_back(id, "id: " + std::to_string(id) + "\nevent: " + kind + "\ndata: " + payload + "\n\n");
    while (ring_.size() > ring_size_) ring_.pop_front();
  }
  changed_.notify_all();
}

LiveEvents::Frames LiveEvents::next(std::uint64_t after_id, std::chrono::milliseconds wait) const {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, wait, [&] { return closed_ || next_id_ - 1 > after_id; });
  Frames out;
  out.closed = closed_;
  out.last_id = next_id_ - 1;
  if (after_id > out.last_id) {
    out.resync = true;  // numbers of an earlier lastcutd run: start over from this one's
    return out;
  }
  if (ring_.empty() || after_id == out.last_id) return out;
  out.resync = ring_.front().first > after_id + 1;
  for (const auto& [id, frame] : ring_)
    if (id > after_id) out.frames.push_back(frame);
  return out;
}

std::uint64_t LiveEvents::newest_id() const {
  std::lock_guard lock(mutex_);
  return next_id_ - 1;
}

nlohmann::json LiveEvents::cutters() const {
  std::lock_guard lock(mutex_);
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, status] : cutters_) out[name] = status;
  return out;
}

void LiveEvents::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

}  // namespace lastcut::daemon
