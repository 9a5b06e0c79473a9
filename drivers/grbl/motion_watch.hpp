#pragma once
// MotionWatch: tells a grbl that still answers but no longer moves from one that is working.
//
// Why: grbl answers status queries from its main loop even when its motion has stopped (seen on
// the grbl 1.1h simulator: "Run" for minutes with MPos frozen and the planner full), so the
// link-silence timeout never fires and a job would wait forever while `lastcut status` shows
// "cutting (19 %)". A working machine changes something at least every few seconds: its position
// (MPos/WPos in the status report), its state, or it acknowledges a line. Hold, Door and Sleep are
// an operator's doing, not a stall: they restart the clock.
#include <string>

namespace lastcut::drivers::grbl {

class MotionWatch {
 public:
  // stall_s: longest time without any sign of progress; 0 turns the watch off.
  MotionWatch(double stall_s, double now_s) : stall_s_(stall_s), last_progress_s_(now_s) {}

  // A line was acknowledged (ok or error:N).
  void on_acknowledged(double now_s) { last_progress_s_ = now_s; }
  // A status report: state ("Run", "Hold", ...) and position text ("MPos:1.000,2.000,0.000").
  void on_status(const std::string& state, const std::string& position, double now_s);
  // True when the job has waited stall_s without progress (and the machine is not paused by an operator).
  bool stalled(double now_s) const { return stall_s_ > 0 && now_s - last_progress_s_ > stall_s_; }
  // "Run at MPos:..." for the message.
  std::string last_seen() const { return state_ + (position_.empty() ? "" : " at " + position_); }

 private:
  double stall_s_;
  double last_progress_s_;
  std::string state_ = "unknown";
  std::string position_;
};

}  // namespace lastcut::drivers::grbl
