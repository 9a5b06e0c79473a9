// Character-counting streamer for grbl (see grbl_job.hpp for the protocol and the Done rule).
#include "drivers/grbl/grbl_job.hpp"

#include <algorithm>
#include <cstdio>
#include <deque>

#include "drivers/grbl/axis_words.hpp"
#include "drivers/grbl/grbl_codes.hpp"
#include "drivers/grbl/grbl_session.hpp"
#include "drivers/grbl/motion_watch.hpp"
#include "drivers/seconds_text.hpp"

namespace lastcut::drivers::grbl {

std::vector<std::string> program_lines(const std::string& program) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < program.size()) {
    size_t end = program.find('\n', start);
    if (end == std::string::npos) end = program.size();
    std::string line = program.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") != std::string::npos) lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

namespace {

class Streamer {
 public:
  Streamer(GrblSession& session, const std::vector<std::string>& lines, const ProgressCallback& progress,
           const std::atomic<bool>& cancel)
      : session_(session),
        lines_(lines),
        progress_(progress),
        cancel_(cancel),
        motion_(session.config().grbl_stall_s, monotonic_s()) {
    for (const auto& line : lines_) bytes_total_ += line.size() + 1;
  }

  SendResult run();

 private:
  SendResult interrupted(const std::string& why, bool stop_machine);
  SendResult alarmed(const std::string& why);
  bool harmless(int code) const {
    const auto& list = session_.config().harmless_grbl_errors;
    return std::find(list.begin(), list.end(), code) != list.end();
  }
  void report(bool force);
  std::string where() const {
    return std::to_string(acked_) + " of " + std::to_string(lines_.size()) + " lines acknowledged";
  }

  GrblSession& session_;
  const std::vector<std::string>& lines_;
  const ProgressCallback& progress_;
  const std::atomic<bool>& cancel_;
  size_t bytes_total_ = 0, bytes_sent_ = 0;
  size_t next_ = 0, acked_ = 0;
  std::deque<size_t> in_flight_;  // line indices sent and not yet acknowledged
  size_t in_flight_bytes_ = 0;
  double last_report_s_ = 0;
  MotionWatch motion_;
};

void Streamer::report(bool force) {
  if (!progress_) return;
  const double now = monotonic_s();
  if (!force && now - last_report_s_ < 0.1) return;
  last_report_s_ = now;
  progress_({bytes_sent_, bytes_total_, acked_, lines_.size(), session_.state()});
}

SendResult Streamer::interrupted(const std::string& why, bool stop_machine) {
  auto& log = session_.log();
  log.push_back("job stopped: " + why);
  std::string reason = why + "; " + where() + "; nothing was resent";
  if (stop_machine) {
    // Lines already in grbl's buffer would still run: hold, then reset to discard them.
    const StepResult hold = session_.feed_hold();
    const StepResult reset = hold.link_lost ? hold : session_.soft_reset();
    if (!hold.ok || !reset.ok) {
      reason += "; could not stop the machine cleanly (" + (!hold.ok ? hold.error : reset.error) + "): check it";
    } else {
      reason += "; machine held and reset";
    }
  }
  report(true);
  return {SendOutcome::Interrupted, reason, log};
}

// grbl in alarm goes on reading the lines already in its receive buffer and refuses each with
// error:9 (G-code locked out): collect those answers now, so none is left on the line for the
// next job to take as the answer to its own first command, and say that none of them ran.
SendResult Streamer::alarmed(const std::string& why) {
  const size_t outstanding = in_flight_.size();
  size_t locked_out = 0, other = 0;
  const double deadline = monotonic_s() + session_.config().timeout_s;
  while (!in_flight_.empty() && monotonic_s() < deadline) {
    Reply reply;
    bool got = false;
    if (auto r = session_.next_reply(reply, got, deadline - monotonic_s()); !r.ok) break;
    if (!got || (reply.kind != ReplyKind::Ok && reply.kind != ReplyKind::Error)) continue;
    in_flight_bytes_ -= lines_[in_flight_.front()].size() + 1;
    in_flight_.pop_front();
    (reply.kind == ReplyKind::Error && reply.code == 9 ? locked_out : other) += 1;
  }
  if (outstanding > 0) {
    session_.log().push_back("of the " + std::to_string(outstanding) + " lines already in the machine's buffer, " +
                             std::to_string(locked_out) + " were refused by the alarm lock (error:9)" +
                             (other ? ", " + std::to_string(other) + " answered otherwise" : "") +
                             (in_flight_.empty() ? "" : ", " + std::to_string(in_flight_.size()) + " not answered"));
  }
  return interrupted(why, false);
}

SendResult Streamer::run() {
  const auto& config = session_.config();
  const size_t rx_bytes = static_cast<size_t>(session_.rx_buffer_bytes());
  const bool counting = config.grbl_streaming != "send-wait";
  double next_poll_s = 0;
  long status_count_at_finish = -1;
  int idle_reports_after_finish = 0;

  while (true) {
    if (cancel_.load()) return interrupted("cancelled by the operator", true);

    // Fill grbl's receive buffer as far as the character count allows.
    while (next_ < lines_.size()) {
      const size_t length = lines_[next_].size() + 1;
      const bool room = counting ? in_flight_bytes_ + length <= rx_bytes : in_flight_.empty();
      if (!room) break;
      if (auto w = session_.write(lines_[next_] + "\n"); !w.ok) {
        return interrupted("link lost while sending line " + std::to_string(next_ + 1) + ": " + w.error, false);
      }
      in_flight_.push_back(next_);
      in_flight_bytes_ += length;
      bytes_sent_ += length;
      ++next_;
    }
    const bool all_acked = next_ == lines_.size() && in_flight_.empty();
    if (all_acked && status_count_at_finish < 0) status_count_at_finish = session_.status_count();

    const double now = monotonic_s();
    if (now >= next_poll_s) {
      if (auto w = session_.write(std::string(1, kStatusQuery)); !w.ok) {
        return interrupted("link lost: " + w.error, false);
      }
      next_poll_s = now + config.status_poll_s;
    }
    if (session_.seconds_since_last_byte() > config.timeout_s) {
      return interrupted("no reply from the machine for " + seconds_text(config.timeout_s), false);
    }

    if (motion_.stalled(monotonic_s())) {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%g", config.grbl_stall_s);
      return interrupted("the machine answers but has neither moved nor taken a line for " + std::string(seconds) +
                             " s (last seen " + motion_.last_seen() + ")",
                         true);
    }

    Reply reply;
    bool got = false;
    if (auto r = session_.next_reply(reply, got, std::max(0.0, next_poll_s - monotonic_s())); !r.ok) {
      return interrupted("link lost: " + r.error, false);
    }
    report(false);
    if (!got) continue;
    switch (reply.kind) {
      case ReplyKind::Ok:
      case ReplyKind::Error: {
        if (in_flight_.empty()) return interrupted("unexpected '" + reply.text + "' with no line outstanding", true);
        const size_t index = in_flight_.front();
        in_flight_.pop_front();
        in_flight_bytes_ -= lines_[index].size() + 1;
        ++acked_;
        motion_.on_acknowledged(monotonic_s());
        if (reply.kind == ReplyKind::Error) {
          const std::string what = "grbl " + reply.text + " at line " + std::to_string(index + 1) + " '" +
                                   lines_[index].substr(0, 40) + "': " + error_meaning(reply.code);
          if (!harmless(reply.code)) return interrupted(what, true);
          session_.log().push_back("ignored (configured harmless): " + what);
        }
        break;
      }
      case ReplyKind::Alarm:
        // grbl has already halted and locked itself; a reset here would only lose the position.
        return alarmed("grbl " + reply.text + ": " + alarm_meaning(reply.code));
      case ReplyKind::Banner:
        return interrupted("the machine restarted during the job (banner '" + reply.text + "')", false);
      case ReplyKind::Garbage:
        return interrupted("unintelligible reply '" + reply.text.substr(0, 40) + "' (link corrupt?)", true);
      case ReplyKind::Status:
        motion_.on_status(reply.state, reply.position, monotonic_s());
        if (all_acked && session_.status_count() > status_count_at_finish) {
          idle_reports_after_finish = reply.state == "Idle" ? idle_reports_after_finish + 1 : 0;
          if (idle_reports_after_finish >= 2) {
            session_.log().push_back("all " + std::to_string(lines_.size()) + " lines acknowledged, machine Idle");
            report(true);
            return {SendOutcome::Done, "job finished: " + where() + ", machine Idle", session_.log()};
          }
        }
        if (reply.state == "Alarm") return alarmed("machine went into alarm");
        break;
      default:
        break;
    }
  }
}

}  // namespace

SendResult run_grbl_job(Transport& link, const CutterConfig& config, const std::string& program,
                        const ProgressCallback& progress, const std::atomic<bool>& cancel) {
  std::vector<std::string> log;
  GrblSession session(link, config, log);
  const auto lines = program_lines(program);
  if (lines.empty()) return {SendOutcome::Failed, "the program has no G-code lines", log};
  if (auto r = session.connect(); !r.ok) return {SendOutcome::Failed, r.error, log};
  const size_t rx_bytes = static_cast<size_t>(session.rx_buffer_bytes());
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].size() + 1 > rx_bytes) {
      return {SendOutcome::Failed,
              "line " + std::to_string(i + 1) + " is " + std::to_string(lines[i].size()) + " characters; the machine's " +
                  std::to_string(rx_bytes) + "-byte buffer cannot hold it",
              log};
    }
  }
  if (session.axis_count() > 0) {
    if (const std::string refused = check_axis_words(lines, session.axis_count()); !refused.empty()) {
      return {SendOutcome::Failed, refused + "; nothing was sent (a rotary-axis profile needs a controller with that axis)",
              log};
    }
  }
  if (cancel.load()) return {SendOutcome::Failed, "cancelled before sending", log};
  Streamer streamer(session, lines, progress, cancel);
  return streamer.run();
}

ProbeResult probe_grbl(Transport& link, const CutterConfig& config) {
  std::vector<std::string> log;
  GrblSession session(link, config, log);
  Reply status;
  if (auto r = session.query_status(status, config.timeout_s); !r.ok) return {false, "no answer", r.error};
  if (status.state == "Idle") return {true, session.state(), ""};
  if (status.state == "Alarm") return {false, session.state(), "machine is in alarm"};
  return {false, session.state(), "machine is busy (" + session.state() + ")"};
}

}  // namespace lastcut::drivers::grbl
