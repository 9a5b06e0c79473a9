#include "daemon/status/status_topics.hpp"

namespace lastcut::daemon {

nlohmann::json cutter_state_payload(const CutterStatus& status, const std::string& station, const std::string& at) {
  return {{"state", status.state}, {"batch", status.batch}, {"reason", status.reason}, {"station", station},
          {"at", at}};
}

nlohmann::json cutter_progress_payload(const CutterStatus& status, const std::string& at) {
  std::size_t percent = 0;
  if (status.lines_total > 0) percent = 100 * status.lines_sent / status.lines_total;
  else if (status.bytes_total > 0) percent = 100 * status.bytes_sent / status.bytes_total;
  return {{"batch", status.batch},           {"lines_sent", status.lines_sent}, {"lines_total", status.lines_total},
          {"bytes_sent", status.bytes_sent}, {"bytes_total", status.bytes_total}, {"percent", percent},
          {"at", at}};
}

nlohmann::json job_event_payload(const JobState& state, const std::string& station) {
  std::string note, at = state.updated_at;
  if (state.history.is_array() && !state.history.empty()) {
    const nlohmann::json& last = state.history.back();
    note = last.value("note", "");
    at = last.value("at", at);
  }
  return {{"job", state.id},
          {"stage", std::string(to_string(state.stage))},
          {"note", note},
          {"reason", state.reason},
          {"order", state.ticket.order},
          {"scan", state.scan_name},
          {"cutter", state.ticket.cutter},
          {"batch", state.batch_id},
          {"station", station},
          {"at", at}};
}

}  // namespace lastcut::daemon
