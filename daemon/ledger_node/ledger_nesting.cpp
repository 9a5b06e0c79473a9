// The nesting step of a ledger node's compute role: a batch the ledger grouped (make_batch for a
// strip material, make_hide_batch for the jobs waiting for a hide that lies on a cutter's table) is
// nested by the same engine steps as on a single station (engine_steps.hpp: build_batch;
// hide_step.hpp: build_hide), written into a scratch folder, published into batches/<id>/ of the
// shared folder, then handed to the ledger (mark_nested, fenced by the batch's lease). Jobs whose
// molds cannot be placed fail with their reason; jobs that did not fit on a hide wait for the next.
#include <spdlog/spdlog.h>
#include <unordered_map>

#include "daemon/ledger_node/ledger_node.hpp"
#include "daemon/station/engine_steps.hpp"
#include "daemon/station/hide_policy.hpp"
#include "daemon/station/hide_step.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/nest/hide_file.hpp"

namespace lastcut::daemon {

std::vector<std::string> LedgerNode::hide_materials() const {
  std::vector<std::string> names;
  for (const auto& [name, material] : config()->materials)
    if (material.kind == MaterialKind::Hide) names.push_back(name);
  return names;
}

Status LedgerNode::nest_on_strip(const ledger::BatchClaim& claim, const MaterialConfig& material,
                                 const CutterSection& cutter, const std::filesystem::path& scratch,
                                 ledger::NestedBatch& nested) {
  const auto settings = config();  // one configuration for the whole step (SIGHUP may replace it)
  std::vector<BatchJobInput> inputs;
  for (std::size_t i = 0; i < claim.job_ids.size(); ++i) {
    inputs.push_back({std::to_string(claim.job_ids[i]), store_.job_dir(claim.job_folders[i])});
  }
  const Result<BatchMade> made =
      build_batch(inputs, material, cutter, settings->paths.machines_dir, settings->batch.nest_time_s, scratch);
  if (!made) return made.status();
  for (const auto& [job_id, reason] : made->rejected) nested.rejected.emplace_back(std::stoll(job_id), reason);
  nested.cut_file = made->cut_file;
  nested.pieces = made->piece_count;
  nested.utilisation = made->utilisation;
  return Status::success();
}

Status LedgerNode::nest_on_hide(const ledger::BatchClaim& claim, const MaterialConfig& material,
                                const CutterSection& cutter, const std::filesystem::path& scratch,
                                ledger::NestedBatch& nested) {
  const auto settings = config();  // one configuration for the whole step (SIGHUP may replace it)
  // build_hide reads the hide file and its sidecar from the batch folder, where they stay with the layout.
  const std::filesystem::path hide_file = store_.absolute(claim.hide_file);
  for (const std::filesystem::path& file : {hide_file, hide_sidecar_path(hide_file)}) {
    std::error_code error;
    if (!std::filesystem::exists(file, error)) continue;  // a hide needs no sidecar
    if (Status copied = copy_file_durably(file, scratch / file.filename()); !copied)
      return Status::failure("the hide file cannot be read from the shared folder: " + copied.error());
  }
  std::vector<HideJobInput> inputs;
  for (std::size_t i = 0; i < claim.job_ids.size(); ++i) {
    const Result<JobTicket> ticket = ticket_from_ledger(claim.job_tickets[i]);
    // job_ids ascend with entry into the ledger: oldest first.
    inputs.push_back({std::to_string(claim.job_ids[i]), store_.job_dir(claim.job_folders[i]), ticket ? ticket->order : "",
                      hide_job_priority(ticket ? ticket->priority : 0, i, claim.job_ids.size())});
  }
  const Result<HideMade> made = build_hide(inputs, scratch, hide_file.filename().string(), material, cutter,
                                           settings->paths.machines_dir, settings->batch.nest_time_s);
  if (!made) return made.status();
  for (const auto& [job_id, reason] : made->rejected) nested.rejected.emplace_back(std::stoll(job_id), reason);
  for (const auto& [job_id, reason] : made->waiting)
    nested.waiting.emplace_back(std::stoll(job_id), "waiting for a hide of " + claim.material + ": " + reason);
  nested.cut_file = made->cut_file;
  nested.pieces = made->piece_count;
  nested.utilisation = made->utilisation;
  if (made->placed.empty()) nested.reason = "no waiting job fitted on hide " + claim.hide_name;
  return Status::success();
}

std::size_t LedgerNode::tell_job_outcomes(const ledger::BatchClaim& claim, const ledger::NestedBatch& nested) {
  struct Outcome {
    JobStage stage;
    const std::string* reason;
  };
  std::unordered_map<long long, Outcome> outcome_of;
  for (const auto& [job_id, reason] : nested.rejected)
    outcome_of.try_emplace(job_id, Outcome{JobStage::Failed, &reason});
  for (const auto& [job_id, reason] : nested.waiting)
    outcome_of.try_emplace(job_id, Outcome{JobStage::Computed, &reason});
  std::size_t kept = 0;
  for (std::size_t i = 0; i < claim.job_ids.size(); ++i) {
    const long long job_id = claim.job_ids[i];
    const std::string& name = claim.job_names[i];
    const auto found = outcome_of.find(job_id);
    if (found == outcome_of.end()) {
      if (nested.cut_file.empty()) continue;  // nothing is cut: the reason is logged for the batch
      ++kept;
      job_changed(job_id, name, claim.job_tickets[i], claim.batch_id, JobStage::Batched, "");
      continue;
    }
    const auto& [stage, reason] = found->second;
    // A waiting job is back among the computed ones: no batch.
    job_changed(job_id, name, claim.job_tickets[i], stage == JobStage::Failed ? claim.batch_id : 0, stage, *reason);
  }
  return kept;
}

void LedgerNode::nest_batch(ledger::LedgerClient& client, const ledger::BatchClaim& claim, const std::string& worker) {
  const auto settings = config();  // one configuration for the whole step (SIGHUP may replace it)
  const bool on_hide = claim.hide_id != 0;
  const std::string label =
      on_hide ? "hide " + claim.hide_name + " (batch " + std::to_string(claim.batch_id) + ")"
              : "batch " + std::to_string(claim.batch_id);
  keeper_->keep(claim.lease);
  ledger::NestedBatch nested;
  const std::filesystem::path final_dir = store_.batch_dir(claim.batch_id);
  auto scratch = store_.scratch_for(final_dir, ledger().node);
  const auto material = settings->materials.find(claim.material);
  const auto cutter = settings->cutters.find(claim.cutter);
  Status made = scratch.status();
  if (made && material == settings->materials.end())
    made = Status::failure("material " + claim.material + " is not configured on node " + ledger().node);
  else if (made && cutter == settings->cutters.end())
    made = Status::failure("cutter " + claim.cutter + " is not configured on node " + ledger().node);
  else if (made) {
    monitor_.begin(worker, label, settings->jobs.compute_timeout_s);
    made = on_hide ? nest_on_hide(claim, material->second, cutter->second, *scratch, nested)
                   : nest_on_strip(claim, material->second, cutter->second, *scratch, nested);
    monitor_.end(worker);
  }
  if (made && !nested.cut_file.empty()) {
    nested.cut_file = store_.relative(final_dir / nested.cut_file);
    made = store_.publish(*scratch, final_dir);
  }
  if (!made) {
    // Not the jobs' fault (no machine profile, the share full). A strip batch fails its jobs with
    // the reason, so that it is seen (`lastcut requeue` hands them back once the cause is mended);
    // the jobs of a hide wait for the next hide.
    nested = {};
    nested.reason = (on_hide ? "hide " + claim.hide_name + " could not be nested: " : "batch could not be made: ") +
                    made.error();
    for (long long id : claim.job_ids) {
      if (on_hide) nested.waiting.emplace_back(id, "waiting for a hide of " + claim.material + ": " + nested.reason);
      else nested.rejected.emplace_back(id, nested.reason);
    }
  }
  std::error_code ignored;
  if (scratch) std::filesystem::remove_all(*scratch, ignored);
  const Status marked = client.mark_nested(claim.lease, nested);
  keeper_->drop(claim.lease);
  if (!marked) {
    spdlog::warn("{}: {}; the nesting is dropped", label, marked.error());
    return;
  }
  const std::size_t kept = tell_job_outcomes(claim, nested);
  if (nested.cut_file.empty()) {
    spdlog::warn("{}: {}; nothing is cut", label, nested.reason.empty() ? "no job could be placed" : nested.reason);
    return;
  }
  if (on_hide) {
    spdlog::info("{}: {} job(s), {} pieces, utilisation of its usable area {:.1f} %, {} job(s) wait; queued for {}",
                 label, kept, nested.pieces, 100.0 * nested.utilisation, nested.waiting.size(), claim.cutter);
  } else {
    spdlog::info("{}: {} job(s), {} pieces nested on {} (utilisation {:.1f} %); queued for {}", label, kept,
                 nested.pieces, claim.material, 100.0 * nested.utilisation, claim.cutter);
  }
}

}  // namespace lastcut::daemon
