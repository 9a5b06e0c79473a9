#pragma once
// GrblSession: the conversation with one grbl controller over a Transport, except streaming
// itself (grbl_job.hpp): reading reply lines, status polling, the connect handshake (banner,
// state, unlock policy, RX buffer size from `$I`), `$` settings sent one at a time, feed hold,
// resume and soft reset. Every step appends what happened to `log` for the operator.
#include <string>
#include <vector>

#include "drivers/cutter.hpp"
#include "drivers/grbl/grbl_replies.hpp"
#include "drivers/transport/transport.hpp"

namespace lastcut::drivers::grbl {

constexpr char kStatusQuery = '?';
constexpr char kFeedHold = '!';
constexpr char kCycleStart = '~';
constexpr char kSoftReset = 0x18;
constexpr int kDefaultRxBufferBytes = 128;  // grbl 1.1 on an ATmega328p; grblHAL reports 1024

struct StepResult {
  bool ok = true;
  bool link_lost = false;
  std::string error;
};

class GrblSession {
 public:
  GrblSession(Transport& link, const CutterConfig& config, std::vector<std::string>& log);

  // Reads replies for up to timeout_s; returns the first complete line in `reply` (got=false on timeout).
  StepResult next_reply(Reply& reply, bool& got, double timeout_s);
  StepResult write(std::string_view bytes);

  // Waits for grbl to answer a status query (it may be booting after the port opened and print
  // its banner first), applies the unlock policy, refuses a busy machine, reads the RX buffer size.
  StepResult connect();
  // One status report, polling every 0.25 s until timeout_s.
  // `stated_timeout_s` (default: timeout_s) is the wait the error message names, when this query is
  // the last part of a longer wait.
  StepResult query_status(Reply& status, double timeout_s, double stated_timeout_s = 0);
  // Sends one line and waits for its ok / error:N (the send-and-wait used for `$` commands).
  StepResult send_and_wait(const std::string& line, std::vector<std::string>* feedback = nullptr);
  // Feed hold: '!' then waits for "Hold:0" (motion fully stopped).
  StepResult feed_hold();
  // Cycle start '~', only once the machine reports Hold:0: resuming a decelerating hold is refused.
  StepResult resume();
  // Ctrl-X: grbl drops its buffers and planner and prints its banner again.
  StepResult soft_reset();

  // Called for every reply next_reply() returns: tracks state and logs the unusual ones.
  void note(const Reply& reply);

  int rx_buffer_bytes() const { return rx_buffer_bytes_; }
  int axis_count() const { return axis_count_; }  // from $I; -1 when the machine did not say
  const std::string& state() const { return state_; }   // "Idle", "Run", "Hold:0", ...
  long status_count() const { return status_count_; }   // status reports seen so far
  double seconds_since_last_byte() const;
  const CutterConfig& config() const { return config_; }
  std::vector<std::string>& log() { return log_; }

 private:
  Transport& link_;
  const CutterConfig& config_;
  std::vector<std::string>& log_;
  std::string pending_;
  std::string state_ = "unknown";
  long status_count_ = 0;
  int rx_buffer_bytes_ = kDefaultRxBufferBytes;
  int axis_count_ = -1;
  double last_byte_time_s_;
};

double monotonic_s();

}  // namespace lastcut::drivers::grbl
