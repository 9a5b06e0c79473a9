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

nlohmann::json job_event_payload(const JobEvent& event, const std::string& station) {
  return {{"job", event.job_id},
          {"stage", std::string(to_string(event.stage))},
          {"note", event.note},
          {"reason", event.reason},
          {"order", event.order},
          {"scan", event.scan_name},
          {"material", event.material},
          {"cutter", event.cutter},
          {"batch", event.batch_id},
          {"station", station},
          {"at", event.at}};
}

nlohmann::json nesting_payload(const NestingStatus& status, const std::string& station, const std::string& at) {
  nlohmann::json payload = to_json(status);
  payload["station"] = station;
  payload["at"] = at;
  return payload;
}

}  // namespace lastcut::daemon
