// Taking a ready scan from the watch folder into the spool, with its sidecar, its hash and the
// duplicate policy. Every file that is taken ends somewhere in the spool: a bad sidecar or a
// cut-off file is claimed and then failed, so the operator finds it in failed/ with the reason.
#include <spdlog/spdlog.h>

#include "daemon/spool_store/job_outcomes.hpp"
#include "daemon/spool_store/spool_store.hpp"
#include "daemon/station/ticket_targets.hpp"
#include "daemon/job/sha256.hpp"
#include "engine/core/durable_file.hpp"

namespace lastcut::daemon {
namespace {

// Reference patterns travel with the job as copies: the watch folder may keep one pattern for
// many jobs, and nothing of the job may depend on the watch folder once it is claimed.
std::string copy_reference_patterns(const std::filesystem::path& sidecar_dir, const std::filesystem::path& job_dir,
                                    const JobTicket& ticket) {
  for (const auto& [mold, file] : ticket.references) {
    const std::filesystem::path from = sidecar_dir / file;
    std::error_code error;
    if (!std::filesystem::is_regular_file(from, error))
      return "reference pattern " + file + " for the " + mold + " mold is not in " + sidecar_dir.string();
    if (Status copied = copy_file_durably(from, job_dir / reference_copy_name(mold, file)); !copied)
      return "reference pattern " + file + " cannot be copied: " + copied.error();
  }
  return {};
}

}  // namespace

void SpoolStore::index_hashes() {
  for (JobFolder folder : {JobFolder::Done, JobFolder::Failed, JobFolder::Held, JobFolder::Work}) {
    for (const std::string& id : spool_->list(folder)) {
      auto state = spool_->read_state(folder, id);
      if (!state || state->sha256.empty() || !state->duplicate_of.empty()) continue;
      hash_to_job_.emplace(state->sha256, id);  // ids sort by time: the first one stays
    }
  }
}

StationStore::Intake SpoolStore::take_scan(const ReadyScan& ready) {
  const auto settings = config();
  const std::string name = ready.scan.filename().string();
  const auto hash = sha256_file_hex(ready.scan);
  if (!hash) return Intake::Taken;  // vanished between listing and hashing; a new event will bring it back
  JobState state;
  state.sha256 = *hash;
  std::string problem = ready.incompleteness;
  if (!ready.sidecar.empty() && problem.empty()) {
    const Result<JobTicket> ticket = read_job_ticket(ready.sidecar);
    if (ticket) state.ticket = *ticket;
    else problem = ticket.error();
  }
  // Settled even for a refused scan: its state in failed/ names where it was meant to go.
  const std::string unknown_target = settle_ticket_targets(state.ticket, *settings, ready.scan);
  if (problem.empty()) problem = unknown_target;
  const auto earlier = hash_to_job_.find(state.sha256);
  const bool duplicate = earlier != hash_to_job_.end();
  if (duplicate) state.duplicate_of = earlier->second;

  const Result<std::string> claim = spool_->claim(ready.scan, ready.sidecar, state);
  if (!claim) {
    // Not in the spool: the scan stays in the watch folder and is offered again.
    spdlog::error("watch folder: {} could not be taken into the spool: {}", name, claim.error());
    return Intake::Taken;
  }
  const std::string& job_id = *claim;
  auto claimed = spool_->read_state(JobFolder::Work, job_id);
  if (!claimed) {
    // In the spool without a readable state: recovery hands it back to the watch folder.
    spdlog::error("job {}: state unreadable right after the claim; left for recovery at the next start", job_id);
    return Intake::Taken;
  }
  known_jobs_.insert(job_id);
  spdlog::info("{}: taken from the watch folder{} (material {}, cutter {})", claimed->label(),
               ready.sidecar.empty() ? "" : " with " + ready.sidecar.filename().string(), claimed->ticket.material,
               claimed->ticket.cutter);
  if (problem.empty())
    problem = copy_reference_patterns(ready.sidecar.parent_path(), spool_->job_dir(JobFolder::Work, job_id),
                                      claimed->ticket);
  if (!problem.empty()) {
    fail_job(*spool_, *claimed, problem);
    return Intake::Taken;
  }
  if (duplicate) {
    const std::string reason = "same scan bytes as job " + state.duplicate_of;
    switch (settings->jobs.duplicate_policy) {
      case DuplicatePolicy::Skip:
        set_job_stage(*spool_, *claimed, JobStage::Skipped, reason + " (duplicate, skipped)",
                      "skipped, but not moved to done/");
        return Intake::Taken;
      case DuplicatePolicy::Hold:
        hold_job(*spool_, *claimed, reason + " (duplicate held by policy)");
        return Intake::Taken;
      case DuplicatePolicy::Process:
        spdlog::info("{}: {} - processed again (policy)", claimed->label(), reason);
        break;
    }
  } else {
    hash_to_job_[state.sha256] = job_id;
  }
  to_compute(job_id);
  return Intake::Taken;
}

}  // namespace lastcut::daemon
