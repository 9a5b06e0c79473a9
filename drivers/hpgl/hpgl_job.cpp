// HP-GL streaming with XON/XOFF, RTS/CTS or the ESC.B handshake (see hpgl_job.hpp).
#include "drivers/hpgl/hpgl_job.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <thread>

#include "drivers/hpgl/hpgl_status.hpp"
#include "drivers/seconds_text.hpp"

namespace lastcut::drivers::hpgl {

namespace {

constexpr char kXon = 0x11, kXoff = 0x13;
constexpr size_t kChunkBytes = 16;
constexpr double kNoProgressFactor = 10;  // x timeout_s: longest a full buffer (or XOFF) may last

double now_s() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

bool parse_number(const std::string& text, int& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

// The device's side of the line: XON/XOFF bytes change `paused`, everything else is answers
// terminated by CR (HP's default output terminator; a following LF is ignored).
class DeviceReader {
 public:
  explicit DeviceReader(Transport& link) : link_(link) {}
  IoStatus pump(double timeout_s) {
    std::string bytes;
    const IoStatus status = link_.read(bytes, timeout_s);
    for (char c : bytes) {
      if (c == kXoff) {
        if (!paused_) paused_since_s_ = now_s();
        paused_ = true;
      } else if (c == kXon) {
        paused_ = false;
      } else if (c != '\n') {
        pending_ += c;
      }
    }
    return status;
  }
  // The next answer, or got=false after timeout_s.
  IoStatus answer(std::string& text, bool& got, double timeout_s) {
    const double deadline = now_s() + timeout_s;
    got = false;
    while (true) {
      const auto cr = pending_.find('\r');
      if (cr != std::string::npos) {
        text = pending_.substr(0, cr);
        pending_.erase(0, cr + 1);
        got = true;
        return {};
      }
      const double left = deadline - now_s();
      if (left <= 0) return {};
      if (IoStatus s = pump(std::min(left, 0.05)); !s.ok) return s;
    }
  }
  bool paused() const { return paused_; }
  double paused_for_s() const { return paused_ ? now_s() - paused_since_s_ : 0; }

 private:
  Transport& link_;
  std::string pending_;
  bool paused_ = false;
  double paused_since_s_ = 0;
};

class HpglJob {
 public:
  HpglJob(Transport& link, const CutterConfig& config, const ProgressCallback& progress, const std::atomic<bool>& cancel)
      : link_(link), config_(config), reader_(link), progress_(progress), cancel_(cancel) {}

  // ESC.<command> with a numeric answer.
  bool query_number(char command, int& value, std::string& error) {
    if (IoStatus w = link_.write(std::string("\x1b.") + command, config_.timeout_s); !w.ok) return fail_io(w, error);
    std::string text;
    bool got = false;
    if (IoStatus r = reader_.answer(text, got, config_.timeout_s); !r.ok) return fail_io(r, error);
    if (!got) {
      error = std::string("no answer to ESC.") + command + " within " + seconds_text(config_.timeout_s);
      return false;
    }
    if (!parse_number(text, value)) {
      error = std::string("unintelligible answer '") + text.substr(0, 30) + "' to ESC." + command + " (wrong baud rate?)";
      return false;
    }
    return true;
  }

  SendResult run(const std::string& program);

 private:
  bool fail_io(const IoStatus& status, std::string& error) {
    error = status.error;
    return false;
  }
  SendResult finish(SendOutcome outcome, const std::string& reason) {
    if (outcome != SendOutcome::Done && sent_ > 0) log_.push_back("stopped after " + std::to_string(sent_) + " bytes; nothing was resent");
    log_.push_back(to_string(outcome) + ": " + reason);
    report("");
    return {outcome, reason, log_};
  }
  SendResult stop(const std::string& why) {
    return finish(sent_ == 0 ? SendOutcome::Failed : SendOutcome::Interrupted,
                  sent_ == 0 ? why : why + " after " + std::to_string(sent_) + " of " + std::to_string(total_) + " bytes; nothing was resent");
  }
  bool check_device_error(std::string& error) {
    int code = 0;
    if (!query_number('E', code, error)) return false;
    if (code != 0) {
      error = "cutter reports device error " + std::to_string(code) + ": " + device_error_meaning(code);
      return false;
    }
    return true;
  }
  void report(const std::string& state) {
    if (progress_) progress_({sent_, total_, 0, 0, state});
  }

  Transport& link_;
  const CutterConfig& config_;
  DeviceReader reader_;
  const ProgressCallback& progress_;
  const std::atomic<bool>& cancel_;
  std::vector<std::string> log_;
  size_t sent_ = 0, total_ = 0;
};

SendResult HpglJob::run(const std::string& program) {
  total_ = program.size();
  const bool escb = config_.hpgl_handshake == "escb";
  const bool xonxoff = !escb && config_.flow == "xonxoff";
  const bool queries = config_.hpgl_status_queries || escb;
  std::string error;
  if (program.empty()) return finish(SendOutcome::Failed, "the program is empty");
  if (queries) {
    int status = 0;
    if (!query_number('O', status, error)) return finish(SendOutcome::Failed, error);
    log_.push_back("ESC.O status " + std::to_string(status) + " on " + link_.describe());
    if (status & 32) return finish(SendOutcome::Failed, "cutter not ready (ESC.O status " + std::to_string(status) + ")");
    int stale = 0;
    if (!query_number('E', stale, error)) return finish(SendOutcome::Failed, error);
    if (stale != 0) log_.push_back("cleared a previous device error " + std::to_string(stale) + ": " + device_error_meaning(stale));
  }
  double wire_free_at_s = now_s();  // when the bytes written so far will have left on the wire
  const int baud = link_.wire_baud();
  double next_error_check_s = now_s() + 1.0, last_report_s = 0, last_accepted_s = now_s();
  while (sent_ < total_) {
    if (cancel_.load()) return stop("cancelled by the operator");
    if (IoStatus r = reader_.pump(0); !r.ok) return stop("link lost: " + r.error);
    if (xonxoff && reader_.paused()) {
      // XOFF while a long path is cut is normal; for many times the silence timeout it is a stall.
      if (reader_.paused_for_s() > kNoProgressFactor * config_.timeout_s) {
        return stop("cutter held XOFF for more than " + seconds_text(kNoProgressFactor * config_.timeout_s));
      }
      if (IoStatus r = reader_.pump(0.01); !r.ok) return stop("link lost: " + r.error);
      continue;
    }
    if (queries && now_s() >= next_error_check_s) {
      if (!check_device_error(error)) return stop(error);
      next_error_check_s = now_s() + 1.0;
    }
    size_t chunk = std::min(kChunkBytes, total_ - sent_);
    if (escb) {
      int free_bytes = 0;
      if (!query_number('B', free_bytes, error)) return stop(error);
      if (free_bytes <= 0) {
        // A full buffer is normal while a long path is cut, but not for ever.
        if (now_s() - last_accepted_s > kNoProgressFactor * config_.timeout_s) {
          return stop("cutter accepted no data for " + seconds_text(kNoProgressFactor * config_.timeout_s));
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        continue;
      }
      last_accepted_s = now_s();
      chunk = std::min(static_cast<size_t>(free_bytes), total_ - sent_);
    }
    // A pty or a USB adapter takes bytes faster than the wire carries them. Model the wire
    // (10 bits per byte) and stay at most one chunk ahead of it, so that at most two chunks are
    // in flight when the cutter sends XOFF, as with a UART.
    if (baud > 0 && !escb) {
      const double wait_s = (wire_free_at_s - now_s()) - static_cast<double>(kChunkBytes) * 10.0 / baud;
      if (wait_s > 0) {
        if (IoStatus r = reader_.pump(wait_s); !r.ok) return stop("link lost: " + r.error);
        continue;
      }
    }
    if (IoStatus w = link_.write(std::string_view(program).substr(sent_, chunk), config_.timeout_s); !w.ok) {
      return stop(w.error);
    }
    sent_ += chunk;
    if (baud > 0) wire_free_at_s = std::max(wire_free_at_s, now_s()) + static_cast<double>(chunk) * 10.0 / baud;
    if (now_s() - last_report_s > 0.1) {
      report("sending");
      last_report_s = now_s();
    }
  }
  if (!queries) {
    if (IoStatus d = link_.drain(config_.timeout_s); !d.ok) return stop(d.error);
    return finish(SendOutcome::Done, "all " + std::to_string(total_) + " bytes sent; this cutter profile cannot confirm completion");
  }
  // OA; goes into the cutter's buffer like any instruction: after the last chunk the buffer may be
  // full, so it waits for XON too (found by the operator page's test at real cutting speed: the
  // cutter reported error 16, its buffer overflowed, when OA; was written during XOFF).
  while (xonxoff && reader_.paused()) {
    if (cancel_.load()) return stop("cancelled by the operator");
    if (reader_.paused_for_s() > kNoProgressFactor * config_.timeout_s) {
      return stop("cutter held XOFF for more than " + seconds_text(kNoProgressFactor * config_.timeout_s));
    }
    if (IoStatus r = reader_.pump(0.01); !r.ok) return stop("link lost: " + r.error);
  }
  // Completion: OA is answered only after every instruction before it was executed. Meanwhile
  // ESC.E every second proves the cutter is alive and catches a device error (answers without commas).
  if (IoStatus w = link_.write("OA;", config_.timeout_s); !w.ok) return stop(w.error);
  double last_answer_s = now_s(), next_keepalive_s = now_s() + 1.0;
  while (true) {
    if (cancel_.load()) return stop("cancelled by the operator while the cutter was finishing");
    std::string text;
    bool got = false;
    if (IoStatus r = reader_.answer(text, got, 0.1); !r.ok) return stop("link lost: " + r.error);
    if (got) {
      last_answer_s = now_s();
      if (std::count(text.begin(), text.end(), ',') == 2) break;  // "x,y,pen": the OA answer
      int code = 0;
      if (!parse_number(text, code)) return stop("unintelligible answer '" + text.substr(0, 30) + "' from the cutter");
      if (code != 0) return stop("cutter reports device error " + std::to_string(code) + ": " + device_error_meaning(code));
      continue;  // the keepalive ESC.E answered "no error"
    }
    if (now_s() - last_answer_s > config_.timeout_s) {
      return stop("cutter stopped answering for " + seconds_text(config_.timeout_s) + " while finishing");
    }
    if (now_s() >= next_keepalive_s) {
      if (IoStatus w = link_.write("\x1b.E", config_.timeout_s); !w.ok) return stop(w.error);
      next_keepalive_s = now_s() + 1.0;
      report("cutting");
    }
  }
  if (!check_device_error(error)) return stop(error);
  return finish(SendOutcome::Done, "cutter finished all " + std::to_string(total_) + " bytes (OA answered, no device error)");
}

}  // namespace

SendResult run_hpgl_job(Transport& link, const CutterConfig& config, const std::string& program,
                        const ProgressCallback& progress, const std::atomic<bool>& cancel) {
  HpglJob job(link, config, progress, cancel);
  return job.run(program);
}

ProbeResult probe_hpgl(Transport& link, const CutterConfig& config) {
  if (!config.hpgl_status_queries && config.hpgl_handshake != "escb") {
    return {true, "unknown", "this cutter profile does not answer status queries; assumed ready"};
  }
  const ProgressCallback none;
  const std::atomic<bool> never{false};
  HpglJob job(link, config, none, never);
  int status = 0;
  std::string error;
  if (!job.query_number('O', status, error)) return {false, "no answer", error};
  if (status & 32) return {false, "not ready", "ESC.O status " + std::to_string(status)};
  return {true, "ready", ""};
}

}  // namespace lastcut::drivers::hpgl
