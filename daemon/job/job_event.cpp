#include "daemon/job/job_event.hpp"

namespace lastcut::daemon {

JobEvent job_event_of(const JobState& state) {
  JobEvent event{state.id,       state.scan_name,  state.ticket.order, state.ticket.material, state.ticket.cutter,
                 state.batch_id, state.stage,      "",                 state.reason,          state.updated_at};
  if (state.history.is_array() && !state.history.empty()) {
    const nlohmann::json& last = state.history.back();
    event.note = last.value("note", "");
    event.at = last.value("at", event.at);
  }
  return event;
}

}  // namespace lastcut::daemon
