#include "drivers/grbl/motion_watch.hpp"

namespace lastcut::drivers::grbl {

void MotionWatch::on_status(const std::string& state, const std::string& position, double now_s) {
  const bool operator_pause = state == "Hold" || state == "Door" || state == "Sleep";
  if (operator_pause || state != state_ || (!position.empty() && position != position_)) last_progress_s_ = now_s;
  state_ = state;
  if (!position.empty()) position_ = position;
}

}  // namespace lastcut::drivers::grbl
