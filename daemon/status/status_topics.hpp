#pragma once
// The MQTT topics and payloads of lastcutd's live status (docs/status-mqtt.md has the table):
//
//   <prefix>/station/<station>/online    retained  "true" | "false" (last will, clean stop)
//   <prefix>/cutter/<cutter>/state       retained  {"state","batch","reason","station","at"}
//   <prefix>/cutter/<cutter>/batch       retained  batch id being cut, waiting or held; "" when idle
//   <prefix>/cutter/<cutter>/progress    retained  {"batch","lines_sent","lines_total","bytes_sent","bytes_total","percent","at"}
//   <prefix>/job/<id>/event              events    {"job","stage","note","reason","order","cutter","batch","station","at"}
//
// Pure functions of their arguments: the publisher decides when, these decide what.
#include <string>

#include <nlohmann/json.hpp>

#include "daemon/job/status_observer.hpp"
#include "daemon/job/job_event.hpp"

namespace lastcut::daemon {

class StatusTopics {
 public:
  explicit StatusTopics(std::string prefix) : prefix_(std::move(prefix)) {}

  std::string station_online(const std::string& station) const { return prefix_ + "/station/" + station + "/online"; }
  std::string cutter_state(const std::string& cutter) const { return prefix_ + "/cutter/" + cutter + "/state"; }
  std::string cutter_batch(const std::string& cutter) const { return prefix_ + "/cutter/" + cutter + "/batch"; }
  std::string cutter_progress(const std::string& cutter) const { return prefix_ + "/cutter/" + cutter + "/progress"; }
  std::string job_event(const std::string& job_id) const { return prefix_ + "/job/" + job_id + "/event"; }

 private:
  std::string prefix_;
};

// `at`: ISO 8601 UTC time of the change (utc_now_iso()).
nlohmann::json cutter_state_payload(const CutterStatus& status, const std::string& station, const std::string& at);
// percent: of the lines acknowledged when the driver counts lines (grbl), else of the bytes
// sent (HPGL, Modbus); 0 before the first progress report. Whole percent, rounded down.
nlohmann::json cutter_progress_payload(const CutterStatus& status, const std::string& at);
// The job's stage after the write, the note of its last history entry (what happened), the
// reason (failed, held, skipped) and what an operator recognises the job by.
nlohmann::json job_event_payload(const JobEvent& event, const std::string& station);

}  // namespace lastcut::daemon
