// Hides (docs/hides.md): the jobs of a hide material wait in a pool per material; a hide file
// dropped into paths.hides is claimed into the spool as a hide batch (batches/BID/ with the hide
// file, its sidecar and batch.json) that lies on its cutter's table until the hide rule
// (daemon/station/hide_policy.hpp, the same on a ledger) finds it due; then up to kHideMaxJobs
// waiting jobs are nested on it, and the cut goes to the cutter through that cutter's worker,
// with the same at-most-once stages as a strip batch. Jobs that did not fit go back to the pool
// with the reason.
#include <algorithm>

#include <spdlog/spdlog.h>

#include "daemon/station/hide_policy.hpp"
#include "daemon/station/hide_step.hpp"
#include "daemon/pipeline/job_outcomes.hpp"
#include "daemon/pipeline/pipeline.hpp"
#include "daemon/station/ticket_targets.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_file.hpp"

namespace lastcut::daemon {

bool Pipeline::is_hide_material(const std::string& material) const {
  const auto settings = config();
  const auto it = settings->materials.find(material);
  return it != settings->materials.end() && it->second.kind == MaterialKind::Hide;
}

void Pipeline::add_to_hide_pool(const JobState& state) {
  auto& pool = hide_waiting_[state.ticket.material];
  if (std::find(pool.begin(), pool.end(), state.id) == pool.end()) pool.push_back(state.id);
  std::sort(pool.begin(), pool.end());  // ids sort by claim time: oldest first
}

void Pipeline::fail_hide(BatchState& batch, const std::string& reason) {
  batch.stage = BatchStage::Empty;
  batch.reason = reason;
  batch.updated_at = utc_now_iso();
  if (Status written = spool_->write_batch(batch); !written)
    spdlog::error("hide batch {}: batch.json not written: {}", batch.id, written.error());
  const auto to = spool_->root() / folder_name(JobFolder::Failed) / batch.id;
  if (Status moved = move_durably(spool_->batch_dir(batch.id), to); !moved) {
    spdlog::error("hide file {}: {}; it stays in {} (not moved to failed/: {})", batch.hide_file, reason,
                  spool_->batch_dir(batch.id).string(), moved.error());
    return;
  }
  spdlog::error("hide file {}: {}; moved to failed/{}", batch.hide_file, reason, batch.id);
}

void Pipeline::take_hide(const ReadyScan& ready) {
  const auto settings = config();
  const std::string name = ready.scan.filename().string();
  BatchState batch;
  batch.id = spool_->new_batch_id();
  batch.stage = BatchStage::Nesting;
  batch.created_at = batch.updated_at = utc_now_iso();
  batch.hide_file = name;
  batch.hide_sidecar = ready.sidecar.empty() ? "" : ready.sidecar.filename().string();
  const auto dir = spool_->batch_dir(batch.id);
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  // batch.json before the files: a crash in between leaves a batch that recovery abandons, and the
  // hide file still in the hides folder, taken again.
  Status claimed = error ? Status::failure("cannot create " + dir.string() + ": " + error.message())
                         : spool_->write_batch(batch);
  if (claimed && !batch.hide_sidecar.empty()) claimed = move_durably(ready.sidecar, dir / batch.hide_sidecar);
  if (claimed) claimed = move_durably(ready.scan, dir / name);
  hide_folder_->forget(name);
  if (!batch.hide_sidecar.empty()) hide_folder_->forget(batch.hide_sidecar);
  if (!claimed) {
    spdlog::error("hides folder: {} could not be taken into the spool: {}", name, claimed.error());
    return;
  }
  HideFile hide;
  try {
    hide = read_hide_file(dir / name);
  } catch (const EngineError& failure) {
    fail_hide(batch, failure.what());
    return;
  } catch (const std::exception& failure) {
    // A reader bug, not a refusal (nlohmann's type_error once escaped here and stopped the daemon): the
    // hide still goes to failed/ with the reason, and the daemon runs on.
    fail_hide(batch, name + ": unreadable hide file (" + failure.what() + ")");
    return;
  }
  batch.hide_id = hide.hide_id;
  if (const std::string unknown = settle_hide_targets(hide.hide_id, hide.material, hide.cutter,
                                                      hide_sidecar_path(name).string(), *settings, batch.material,
                                                      batch.cutter);
      !unknown.empty()) {
    fail_hide(batch, unknown);
    return;
  }
  if (Status written = spool_->write_batch(batch); !written) {
    fail_hide(batch, "hide " + hide.hide_id + ": batch.json not written: " + written.error());
    return;
  }
  spdlog::info("hide {} ({}, {:.2f} m^2) lies on cutter {}: batch {} for the computed jobs of {}", hide.hide_id, name,
               hide.area_m2, batch.cutter, batch.id, batch.material);
  loaded_hides_.push_back({batch.id, Clock::now()});
}

bool Pipeline::computing_material(const std::string& material) const {
  for (const std::string& id : known_jobs_) {
    const auto state = spool_->read_state(JobFolder::Work, id);
    if (state && state->stage == JobStage::Claimed && state->ticket.material == material) return true;
  }
  return false;
}

void Pipeline::nest_due_hides(Clock::time_point now) {
  const double window_s = config()->batch.window_s;
  for (auto loaded = loaded_hides_.begin(); loaded != loaded_hides_.end();) {
    auto batch = spool_->read_batch(loaded->batch_id);
    if (!batch || batch->stage != BatchStage::Nesting) {  // gone meanwhile (an operator)
      loaded = loaded_hides_.erase(loaded);
      continue;
    }
    std::vector<std::string>& pool = hide_waiting_[batch->material];
    std::erase_if(pool, [&](const std::string& id) {
      const auto state = spool_->read_state(JobFolder::Work, id);
      return !state || state->stage != JobStage::Computed || !state->stage_problem.empty();
    });
    const double waited_s = std::chrono::duration<double>(now - loaded->since).count();
    if (pool.empty() || !hide_is_due(pool.size(), computing_material(batch->material), waited_s, window_s)) {
      ++loaded;
      continue;
    }
    const std::size_t offered = std::min<std::size_t>(pool.size(), kHideMaxJobs);
    batch->job_ids.assign(pool.begin(), pool.begin() + static_cast<std::ptrdiff_t>(offered));
    pool.erase(pool.begin(), pool.begin() + static_cast<std::ptrdiff_t>(offered));
    batch->updated_at = utc_now_iso();
    if (Status written = spool_->write_batch(*batch); !written) {
      // The jobs stay in the pool; the hide is offered again next turn.
      pool.insert(pool.begin(), batch->job_ids.begin(), batch->job_ids.end());
      spdlog::error("hide {} (batch {}): batch.json not written: {}", batch->hide_id, batch->id, written.error());
      ++loaded;
      continue;
    }
    for (const std::string& id : batch->job_ids) {
      auto state = spool_->read_state(JobFolder::Work, id);
      if (!state) continue;
      state->batch_id = batch->id;
      state->reason.clear();
      set_job_stage(*spool_, *state, JobStage::Batched, "nested on hide " + batch->hide_id + " (batch " + batch->id + ")",
                    "not part of hide batch " + batch->id + ": state not written");
    }
    spdlog::info("hide {} on cutter {}: nesting {} waiting job(s) of {} in batch {}{}", batch->hide_id, batch->cutter,
                 batch->job_ids.size(), batch->material, batch->id,
                 pool.empty() ? "" : " (" + std::to_string(pool.size()) + " wait for the next hide)");
    tasks_.push({true, batch->id});
    loaded = loaded_hides_.erase(loaded);
  }
}

void Pipeline::build_hide_task(BatchState& batch, const std::string& worker) {
  const auto settings = config();
  std::vector<HideJobInput> inputs;
  std::map<std::string, JobState> states;
  for (const std::string& id : batch.job_ids) {
    auto state = spool_->read_state(JobFolder::Work, id);
    if (!state || state->batch_id != batch.id) continue;
    states.emplace(id, *state);
  }
  // batch.job_ids is oldest first.
  for (const std::string& id : batch.job_ids) {
    const auto it = states.find(id);
    if (it == states.end()) continue;
    inputs.push_back({id, spool_->job_dir(JobFolder::Work, id), it->second.ticket.order,
                      hide_job_priority(it->second.ticket.priority, inputs.size(), batch.job_ids.size())});
  }
  const auto material = settings->materials.find(batch.material);
  const auto cutter = settings->cutters.find(batch.cutter);
  Result<HideMade> outcome = Status::failure("material " + batch.material + " or cutter " + batch.cutter +
                                             " is no longer configured");
  if (material != settings->materials.end() && cutter != settings->cutters.end()) {
    monitor_.begin(worker, "nesting hide " + batch.hide_id, settings->jobs.compute_timeout_s);
    outcome = build_hide(inputs, spool_->batch_dir(batch.id), batch.hide_file, material->second, cutter->second,
                         settings->paths.machines_dir, settings->batch.nest_time_s);
    monitor_.end(worker);
  }
  std::vector<std::string> kept;
  std::vector<std::string> back_to_pool;
  for (auto& [id, state] : states) {
    std::string waits;
    if (!outcome) {
      waits = "hide " + batch.hide_id + " could not be nested: " + outcome.error();
    } else if (auto rejected = outcome->rejected.find(id); rejected != outcome->rejected.end()) {
      fail_job(*spool_, state, rejected->second);
      continue;
    } else if (auto waiting = outcome->waiting.find(id); waiting != outcome->waiting.end()) {
      waits = waiting->second;
    } else {
      kept.push_back(id);
      continue;
    }
    state.batch_id.clear();
    state.reason = "waiting for a hide of " + batch.material + ": " + waits;
    set_job_stage(*spool_, state, JobStage::Computed, state.reason);
    back_to_pool.push_back(id);
  }
  {
    std::lock_guard lock(computed_mutex_);
    computed_.insert(computed_.end(), back_to_pool.begin(), back_to_pool.end());
  }
  batch.job_ids = kept;
  batch.updated_at = utc_now_iso();
  if (!outcome || kept.empty()) {
    batch.stage = BatchStage::Empty;
    batch.reason = !outcome           ? outcome.error()
                   : inputs.empty()   ? "no piece of " + batch.material + " was waiting for hide " + batch.hide_id
                                      : "no waiting job fitted on hide " + batch.hide_id;
    if (Status written = spool_->write_batch(batch); !written)
      spdlog::error("hide batch {}: {}, but batch.json not written: {}", batch.id, batch.reason, written.error());
    spdlog::warn("hide {} (batch {}): {}; nothing is cut", batch.hide_id, batch.id, batch.reason);
    return;
  }
  batch.stage = BatchStage::Queued;
  batch.cut_file = outcome->cut_file;
  batch.utilisation = outcome->utilisation;
  batch.piece_count = outcome->piece_count;
  if (Status written = spool_->write_batch(batch); !written) {
    report_batch_problem(*spool_, batch, "nested, but not queued: batch.json not written: " + written.error());
    return;
  }
  spdlog::info("hide {} (batch {}): {} job(s), {} pieces, utilisation of its usable area {:.1f} %, {} job(s) wait; "
               "queued for {}",
               batch.hide_id, batch.id, kept.size(), batch.piece_count, 100.0 * batch.utilisation, back_to_pool.size(),
               batch.cutter);
  enqueue_batch(batch);
}

}  // namespace lastcut::daemon
