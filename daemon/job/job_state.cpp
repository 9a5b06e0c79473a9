#include "daemon/job/job_state.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>

namespace lastcut::daemon {
namespace {

// Sets `stage` from json["stage"]; a missing or unknown value gives `held` with the problem as
// `problem` and `reason`, never a guess.
template <typename Stage, typename Parse>
void read_stage(const nlohmann::json& json, std::string_view file_name, Parse parse, Stage held, Stage& stage,
                std::string& problem, std::string& reason) {
  const auto stored = json.find("stage");
  if (stored == json.end()) {
    problem = missing_stage_reason(file_name);
  } else {
    const std::string text = stored->is_string() ? stored->template get<std::string>() : stored->dump();
    if (const auto parsed = parse(text)) {
      stage = *parsed;
      return;
    }
    problem = unknown_stage_reason(file_name, text);
  }
  stage = held;
  reason = problem;
}

}  // namespace

std::string utc_now_iso() {
  const auto now = std::chrono::system_clock::now();
  const auto seconds = std::chrono::system_clock::to_time_t(now);
  const auto millis =
      std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[96];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900, utc.tm_mon + 1,
                utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, static_cast<int>(millis));
  return text;
}

void JobState::advance(JobStage new_stage, const std::string& note) {
  stage = new_stage;
  updated_at = utc_now_iso();
  nlohmann::json entry{{"at", updated_at}, {"stage", to_string(new_stage)}};
  if (!note.empty()) entry["note"] = note;
  history.push_back(entry);
}

bool JobState::next_part() {
  if (part + 1 >= static_cast<int>(parts.size())) return false;
  ++part;
  take_current_part();
  batch_id.clear();
  return true;
}

void JobState::take_parts(const std::vector<JobPart>& computed) {
  ResumedParts resumed = resume_parts(parts, part, computed, {ticket.material, ticket.cutter, piece_count, {}});
  parts = std::move(resumed.parts);
  part = resumed.part;
  if (!parts.empty()) take_current_part();
}

void JobState::take_current_part() {
  const JobPart& current = parts[static_cast<std::size_t>(part)];
  ticket.material = current.material;
  ticket.cutter = current.cutter;
  piece_count = current.pieces;
}

std::string JobState::label() const {
  std::string text = ticket.order.empty() ? "scan " + scan_name : "order " + ticket.order + " (" + scan_name + ")";
  return text + " [job " + id + "]";
}

nlohmann::json to_json(const JobState& state) {
  nlohmann::json json{{"id", state.id},
                        {"scan", state.scan_name},
                        {"sidecar", state.sidecar_name},
                        {"sha256", state.sha256},
                        {"stage", to_string(state.stage)},
                        {"reason", state.reason},
                        {"attempts", state.attempts},
                        {"pieces", state.piece_count},
                        {"ticket", ticket_to_json(state.ticket)},
                        {"batch", state.batch_id},
                        {"duplicate_of", state.duplicate_of},
                        {"claimed_at", state.claimed_at},
                        {"updated_at", state.updated_at},
                        {"history", state.history}};
  if (!state.parts.empty()) json["parts"] = parts_to_json(state.parts), json["part"] = state.part;
  return json;
}

JobState job_state_from_json(const nlohmann::json& json) {
  JobState state;
  state.id = json.value("id", "");
  state.scan_name = json.value("scan", "");
  state.sidecar_name = json.value("sidecar", "");
  state.sha256 = json.value("sha256", "");
  state.reason = json.value("reason", "");
  read_stage(json, "state.json", parse_job_stage, JobStage::Held, state.stage, state.stage_problem, state.reason);
  state.attempts = json.value("attempts", 0);
  state.piece_count = json.value("pieces", 0);
  if (json.contains("ticket")) state.ticket = ticket_from_json(json.at("ticket"));
  state.batch_id = json.value("batch", "");
  state.duplicate_of = json.value("duplicate_of", "");
  state.claimed_at = json.value("claimed_at", "");
  state.updated_at = json.value("updated_at", "");
  if (json.contains("history") && json.at("history").is_array()) state.history = json.at("history");
  if (json.contains("parts")) state.parts = parts_from_json(json.at("parts"));
  state.part = json.value("part", 0);
  return state;
}

nlohmann::json to_json(const BatchState& state) {
  nlohmann::json json{{"id", state.id},
                        {"material", state.material},
                        {"cutter", state.cutter},
                        {"jobs", state.job_ids},
                        {"stage", to_string(state.stage)},
                        {"reason", state.reason},
                        {"cut_file", state.cut_file},
                        {"utilisation", state.utilisation},
                        {"pieces", state.piece_count},
                        {"created_at", state.created_at},
                        {"updated_at", state.updated_at},
                        {"cutter_answer", state.cutter_answer}};
  if (!state.hide_file.empty()) {
    json["hide"] = {{"id", state.hide_id}, {"file", state.hide_file}, {"sidecar", state.hide_sidecar}};
  }
  return json;
}

BatchState batch_state_from_json(const nlohmann::json& json) {
  BatchState state;
  state.id = json.value("id", "");
  state.material = json.value("material", "");
  state.cutter = json.value("cutter", "");
  if (json.contains("jobs")) state.job_ids = json.at("jobs").get<std::vector<std::string>>();
  state.reason = json.value("reason", "");
  read_stage(json, "batch.json", parse_batch_stage, BatchStage::Held, state.stage, state.stage_problem, state.reason);
  state.cut_file = json.value("cut_file", "");
  state.utilisation = json.value("utilisation", 0.0);
  state.piece_count = json.value("pieces", 0);
  state.created_at = json.value("created_at", "");
  state.updated_at = json.value("updated_at", "");
  if (json.contains("cutter_answer")) state.cutter_answer = json.at("cutter_answer");
  if (json.contains("hide") && json.at("hide").is_object()) {
    const nlohmann::json& hide = json.at("hide");
    state.hide_id = hide.value("id", "");
    state.hide_file = hide.value("file", "");
    state.hide_sidecar = hide.value("sidecar", "");
  }
  return state;
}

}  // namespace lastcut::daemon
