// GrblSession: handshake, status, settings, hold/resume/reset for grbl 1.1 and grblHAL.
#include "drivers/grbl/grbl_session.hpp"

#include <chrono>

#include "drivers/grbl/grbl_codes.hpp"
#include "drivers/seconds_text.hpp"

namespace lastcut::drivers::grbl {

double monotonic_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

GrblSession::GrblSession(Transport& link, const CutterConfig& config, std::vector<std::string>& log)
    : link_(link), config_(config), log_(log), last_byte_time_s_(monotonic_s()) {}

double GrblSession::seconds_since_last_byte() const { return monotonic_s() - last_byte_time_s_; }

StepResult GrblSession::write(std::string_view bytes) {
  const IoStatus status = link_.write(bytes, config_.timeout_s);
  if (!status.ok) return {false, status.closed, status.error};
  return {};
}

StepResult GrblSession::next_reply(Reply& reply, bool& got, double timeout_s) {
  got = false;
  const double deadline = monotonic_s() + timeout_s;
  while (true) {
    const auto newline = pending_.find('\n');
    if (newline != std::string::npos) {
      std::string line = pending_.substr(0, newline);
      pending_.erase(0, newline + 1);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      reply = classify_reply(line);
      if (reply.kind == ReplyKind::Empty) continue;
      note(reply);
      got = true;
      return {};
    }
    // A line longer than any grbl reply without a newline is noise, not a reply still arriving.
    if (pending_.size() > 512) {
      reply = classify_reply(pending_.substr(0, 64));
      reply.kind = ReplyKind::Garbage;
      pending_.clear();
      got = true;
      return {};
    }
    const double left = deadline - monotonic_s();
    const size_t before = pending_.size();
    const IoStatus status = link_.read(pending_, left > 0 ? left : 0);
    if (!status.ok) return {false, status.closed, status.error};
    if (pending_.size() > before) last_byte_time_s_ = monotonic_s();
    if (pending_.size() == before && left <= 0) return {};
  }
}

void GrblSession::note(const Reply& reply) {
  switch (reply.kind) {
    case ReplyKind::Status:
      ++status_count_;
      state_ = reply.substate >= 0 ? reply.state + ":" + std::to_string(reply.substate) : reply.state;
      break;
    case ReplyKind::Error:
      log_.push_back("< " + reply.text + " (" + error_meaning(reply.code) + ")");
      break;
    case ReplyKind::Alarm:
      state_ = "Alarm";
      log_.push_back("< " + reply.text + " (" + alarm_meaning(reply.code) + ")");
      break;
    case ReplyKind::Ok:
    case ReplyKind::Empty:
    case ReplyKind::Setting:
      break;
    case ReplyKind::Banner:
    case ReplyKind::Options:
    case ReplyKind::Feedback:
      log_.push_back("< " + reply.text);
      break;
    case ReplyKind::Garbage:
      log_.push_back("< unintelligible reply: '" + reply.text.substr(0, 40) + "'");
      break;
  }
}

StepResult GrblSession::query_status(Reply& status, double timeout_s, double stated_timeout_s) {
  if (stated_timeout_s <= 0) stated_timeout_s = timeout_s;
  const double deadline = monotonic_s() + timeout_s;
  double next_poll = 0;
  std::string last_garbage;
  while (monotonic_s() < deadline) {
    if (monotonic_s() >= next_poll) {
      if (auto w = write(std::string(1, kStatusQuery)); !w.ok) return w;
      next_poll = monotonic_s() + 0.25;
    }
    bool got = false;
    Reply reply;
    if (auto r = next_reply(reply, got, 0.05); !r.ok) return r;
    if (got && reply.kind == ReplyKind::Status) {
      status = reply;
      return {};
    }
    // A partial line right after opening the port (the tail of a banner printed before we
    // flushed) is normal; only a link that never answers sensibly is an error.
    if (got && reply.kind == ReplyKind::Garbage) last_garbage = reply.text.substr(0, 40);
  }
  if (!last_garbage.empty()) {
    return {false, false, "only unintelligible replies ('" + last_garbage + "') within " +
                              seconds_text(stated_timeout_s) + " (wrong baud rate or not a grbl machine?)"};
  }
  return {false, false, "no status reply from grbl within " + seconds_text(stated_timeout_s) + " on " +
                            link_.describe()};
}

StepResult GrblSession::send_and_wait(const std::string& line, std::vector<std::string>* feedback) {
  if (auto w = write(line + "\n"); !w.ok) return w;
  log_.push_back("> " + line);
  const double deadline = monotonic_s() + config_.timeout_s;
  while (monotonic_s() < deadline) {
    bool got = false;
    Reply reply;
    if (auto r = next_reply(reply, got, deadline - monotonic_s()); !r.ok) return r;
    if (!got) break;
    switch (reply.kind) {
      case ReplyKind::Ok: return {};
      case ReplyKind::Error: return {false, false, "'" + line + "' refused: " + reply.text + " (" + error_meaning(reply.code) + ")"};
      case ReplyKind::Alarm: return {false, false, reply.text + " (" + alarm_meaning(reply.code) + ")"};
      case ReplyKind::Garbage: return {false, false, "unintelligible reply to '" + line + "'"};
      default:
        if (feedback) feedback->push_back(reply.text);
    }
  }
  return {false, false, "no reply to '" + line + "' within " + seconds_text(config_.timeout_s)};
}

StepResult GrblSession::connect() {
  // Answers still on the line from an earlier session (a job cut short, a daemon killed) would
  // be taken for the answers to our first commands: read them away first.
  std::vector<std::string> stale;
  for (const double deadline = monotonic_s() + 1.0; monotonic_s() < deadline;) {
    Reply reply;
    bool got = false;
    if (auto r = next_reply(reply, got, 0.05); !r.ok) return r;
    if (!got) break;
    stale.push_back(reply.text);
  }
  if (!stale.empty()) {
    log_.push_back("discarded " + std::to_string(stale.size()) + " replies left from before (first '" + stale.front() + "')");
  }
  Reply status;
  if (auto r = query_status(status, config_.timeout_s); !r.ok) return r;
  log_.push_back("grbl state " + state_ + " on " + link_.describe());
  if (status.state == "Alarm") {
    if (config_.grbl_unlock != "unlock") {
      return {false, false, "machine is in alarm: check it, home or unlock it at the machine (or set grbl unlock policy to 'unlock')"};
    }
    if (auto r = send_and_wait("$X"); !r.ok) return r;
    if (auto r = query_status(status, config_.timeout_s); !r.ok) return r;
  }
  if (status.state != "Idle") {
    return {false, false, "machine is busy (state " + state_ + "): another job is running or it is held"};
  }
  if (config_.grbl_rx_buffer_bytes > 0) {
    rx_buffer_bytes_ = config_.grbl_rx_buffer_bytes;
  } else {
    std::vector<std::string> info;
    if (auto r = send_and_wait("$I", &info); !r.ok) {
      log_.push_back("$I not answered (" + r.error + "); assuming a " + std::to_string(kDefaultRxBufferBytes) + "-byte buffer");
    }
    for (const auto& line : info) {
      const Reply reply = classify_reply(line);
      if (reply.kind != ReplyKind::Options) continue;
      if (reply.rx_buffer_bytes > 0) rx_buffer_bytes_ = reply.rx_buffer_bytes;
      // grbl 1.1's [OPT:...] has no axis field: it always has X, Y and Z.
      axis_count_ = reply.axis_count > 0 ? reply.axis_count : 3;
    }
  }
  log_.push_back("receive buffer " + std::to_string(rx_buffer_bytes_) + " bytes");
  for (const auto& setting : config_.grbl_settings) {
    if (auto r = send_and_wait(setting); !r.ok) return r;
  }
  return {};
}

StepResult GrblSession::feed_hold() {
  if (auto w = write(std::string(1, kFeedHold)); !w.ok) return w;
  log_.push_back("> ! (feed hold)");
  const double deadline = monotonic_s() + config_.timeout_s;
  // The first report may answer a '?' sent before the '!': an Idle in it can be a planner that ran
  // dry for a moment under load and is about to start the next block. Idle counts only when two
  // reports in a row say so; Hold:0 can only come after the hold.
  int idle_reports = 0;
  while (monotonic_s() < deadline) {
    Reply status;
    // The message names the whole stop's wait, not what was left of it when the replies stopped.
    if (auto r = query_status(status, deadline - monotonic_s(), config_.timeout_s); !r.ok) return r;
    idle_reports = status.state == "Idle" ? idle_reports + 1 : 0;
    if (state_ == "Hold:0" || idle_reports >= 2 || status.state == "Alarm") return {};
  }
  return {false, false, "machine did not come to a stop (Hold:0) within " + seconds_text(config_.timeout_s)};
}

StepResult GrblSession::resume() {
  Reply status;
  if (auto r = query_status(status, config_.timeout_s); !r.ok) return r;
  if (state_ != "Hold:0") return {false, false, "not resuming: machine state is " + state_ + ", not a completed hold (Hold:0)"};
  if (auto w = write(std::string(1, kCycleStart)); !w.ok) return w;
  log_.push_back("> ~ (cycle start)");
  return {};
}

StepResult GrblSession::soft_reset() {
  if (auto w = write(std::string(1, kSoftReset)); !w.ok) return w;
  log_.push_back("> ctrl-X (soft reset)");
  const double deadline = monotonic_s() + config_.timeout_s;
  while (monotonic_s() < deadline) {
    bool got = false;
    Reply reply;
    if (auto r = next_reply(reply, got, deadline - monotonic_s()); !r.ok) return r;
    if (got && reply.kind == ReplyKind::Banner) return {};
  }
  return {false, false, "grbl did not restart after soft reset within " + seconds_text(config_.timeout_s)};
}

}  // namespace lastcut::drivers::grbl
