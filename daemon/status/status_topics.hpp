#pragma once
// The MQTT topics and payloads of lastcutd's live status (docs/status-mqtt.md has the table):
//
//   <prefix>/station/<station>/online    retained  "true" | "false" (last will, clean stop)
//   <prefix>/cutter/<cutter>/state       retained  {"state","batch","reason","station","at"}
//   <prefix>/cutter/<cutter>/batch       retained  batch id being cut, waiting or held; "" when idle
//   <prefix>/cutter/<cutter>/progress    retained  {"batch","lines_sent","lines_total","bytes_sent","bytes_total","percent","at"}
//   <prefix>/job/<id>/event              events    {"job","stage","note","reason","order","cutter","batch","station","at"}
//   <prefix>/material/<material>/nesting retained  the material's last nesting (nesting_payload)
//   <prefix>/hide/<hide>/nesting         retained  the hide's nesting (nesting_payload)
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
  // Material names and hide ids come from the shop's files: '/', '+' and '#' become '_' in the topic.
  std::string material_nesting(const std::string& material) const { return prefix_ + "/material/" + topic_level(material) + "/nesting"; }
  std::string hide_nesting(const std::string& hide) const { return prefix_ + "/hide/" + topic_level(hide) + "/nesting"; }
  static std::string topic_level(std::string name) {
    for (char& c : name)
      if (c == '/' || c == '+' || c == '#') c = '_';
    return name;
  }

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
// {"material","hide","batch","cutter","pieces_placed","pieces_waiting","jobs_placed","jobs_waiting",
//  "utilisation","station","at"}
nlohmann::json nesting_payload(const NestingStatus& status, const std::string& station, const std::string& at);

}  // namespace lastcut::daemon
