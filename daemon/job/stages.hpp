#pragma once
// The stages of a job (state.json) and of a batch (batch.json), and their one spelling on disk.
// Each enum has one table of names (stages.cpp); parse_* refuses any other text, so a state file
// with a missing or unknown stage is never taken for some stage: the reader holds it instead.
// Callers switch over these enums without `default:`, so -Wswitch names every place a new
// stage must be handled.
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace lastcut::daemon {

// Road of a job: claimed (scan in the spool, molds not yet made) -> computed (molds written) ->
// batched (part of batch B, cut file made) -> sending (bytes may have reached the cutter) ->
// cut. Side exits: failed (bad input), held (needs an operator), skipped (duplicate, skip policy).
enum class JobStage { Claimed, Computed, Batched, Sending, Cut, Failed, Held, Skipped };

// Road of a batch: nesting -> queued -> sending -> cut | held. Side exits: abandoned (lastcutd
// stopped while nesting; its jobs are nested again), empty (no job left to cut).
enum class BatchStage { Nesting, Queued, Sending, Cut, Held, Abandoned, Empty };

// Nesting, queued or sending: the batch still carries its jobs on (they wait for it).
bool in_progress(BatchStage stage);
// Cut, failed, held or skipped: the job has left work/ (or is leaving it).
bool has_ended(JobStage stage);

std::string_view to_string(JobStage stage);
std::string_view to_string(BatchStage stage);
std::optional<JobStage> parse_job_stage(std::string_view text);
std::optional<BatchStage> parse_batch_stage(std::string_view text);
// Every value, in declaration order (for tests and listings).
std::span<const JobStage> all_job_stages();
std::span<const BatchStage> all_batch_stages();

// Why a stage read from `file_name` ("state.json", "batch.json") cannot be used, for a stored
// value that is missing (nullopt) or not a known stage: "batch.json has no stage",
// "batch.json has an unknown stage 'xyz'".
std::string missing_stage_reason(std::string_view file_name);
std::string unknown_stage_reason(std::string_view file_name, std::string_view text);

}  // namespace lastcut::daemon
