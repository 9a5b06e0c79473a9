#pragma once
// The per-job state file (state.json in the job's folder) and the per-batch state file
// (batch.json). Both are replaced atomically (engine/core/durable_file.hpp), so after any crash they hold
// a complete earlier or later version.
// The stages are in stages.hpp; the folder (work/done/failed/held) follows the job's stage.
//
// A file whose stage is missing or unknown reads as Held with `stage_problem` set (and as the
// reason): whoever finds it holds the job or batch for an operator and says why.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "daemon/job/job_parts.hpp"
#include "daemon/job/job_ticket.hpp"
#include "daemon/job/stages.hpp"

namespace lastcut::daemon {

struct JobState {
  std::string id;
  std::string scan_name;     // original file name, kept in the job folder
  std::string sidecar_name;  // "" when the scan came without a sidecar
  std::string sha256;        // of the scan bytes
  JobStage stage = JobStage::Claimed;
  std::string reason;        // why failed, held or skipped (operator's words)
  std::string stage_problem; // not stored: set when state.json's stage was missing or unknown
  int attempts = 0;          // computations started (a crash or hang counts)
  int piece_count = 0;       // molds made x quantity (set once computed)
  JobTicket ticket;          // material and cutter already resolved to configured names (a part's: the current part's)
  std::vector<JobPart> parts;  // a job of several materials, cut one after another (job_parts.hpp); else empty
  int part = 0;                // the part being nested or cut now
  std::string batch_id;
  std::string duplicate_of;  // job id whose scan had the same bytes
  std::string claimed_at;    // ISO 8601 UTC
  std::string updated_at;
  nlohmann::json history = nlohmann::json::array();  // [{at, stage, note}]

  // A job of several materials whose current part is cut and another follows: the next part becomes
  // current (its material, cutter and pieces; no batch) and true is returned. False after the last.
  bool next_part();
  // A job computed again (a requeue) with `computed` as its parts (empty for one material, whose
  // pieces are then piece_count of the ticket's material): where it goes on is resume_parts'
  // (job_parts.hpp), so the parts already cut, split over hides or not, are not cut again. The current
  // part's targets become the job's.
  void take_parts(const std::vector<JobPart>& computed);
  // The current part's material, cutter and pieces become the job's (parts[part] must exist).
  void take_current_part();
  // Moves to `new_stage`, stamping the time and appending to the history.
  void advance(JobStage new_stage, const std::string& note = "");
  // "order 4711 (scan last.stl, job 20261121-235000-001)": how log lines name a job.
  std::string label() const;
};

nlohmann::json to_json(const JobState& state);
JobState job_state_from_json(const nlohmann::json& json);

struct BatchState {
  std::string id;
  std::string material;
  std::string cutter;
  std::vector<std::string> job_ids;
  BatchStage stage = BatchStage::Queued;
  std::string reason;
  std::string stage_problem;     // not stored: set when batch.json's stage was missing or unknown
  std::string cut_file;          // file name inside the batch folder
  double utilisation = 0;        // piece area / used material area (0..1)
  int piece_count = 0;
  std::string created_at;
  std::string updated_at;
  nlohmann::json cutter_answer = nlohmann::json::array();  // device log lines
  // A hide batch (docs/hides.md): the hide on the cutter's table, its file (and sidecar) kept in the
  // batch folder. Empty for strip batches.
  std::string hide_id;
  std::string hide_file;
  std::string hide_sidecar;
};

nlohmann::json to_json(const BatchState& state);
BatchState batch_state_from_json(const nlohmann::json& json);

// Current UTC time as 2026-11-21T23:50:00.123Z.
std::string utc_now_iso();

}  // namespace lastcut::daemon
