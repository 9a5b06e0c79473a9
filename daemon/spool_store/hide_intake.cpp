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
#include "daemon/spool_store/job_outcomes.hpp"
#include "daemon/spool_store/spool_store.hpp"
#include "daemon/station/ticket_targets.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_file.hpp"

namespace lastcut::daemon {

bool SpoolStore::is_hide_material(const std::string& material) const {
  const auto settings = config();
  const auto it = settings->materials.find(material);
  return it != settings->materials.end() && it->second.kind == MaterialKind::Hide;
}

void SpoolStore::add_to_hide_pool(const JobState& state) {
  auto& pool = hide_waiting_[state.ticket.material];
  hide_waiting_pieces_[state.id] = state.piece_count;
  if (std::find(pool.begin(), pool.end(), state.id) == pool.end()) pool.push_back(state.id);
  std::sort(pool.begin(), pool.end());  // ids sort by claim time: oldest first
}

void SpoolStore::fail_hide(BatchState& batch, const std::string& reason) {
  set_batch_stage(*spool_, batch, BatchStage::Empty, reason, BatchLine::ByCaller);
  const auto to = spool_->root() / folder_name(JobFolder::Failed) / batch.id;
  if (Status moved = move_durably(spool_->batch_dir(batch.id), to); !moved) {
    spdlog::error("hide file {}: {}; it stays in {} (not moved to failed/: {})", batch.hide_file, reason,
                  spool_->batch_dir(batch.id).string(), moved.error());
    return;
  }
  spdlog::error("hide file {}: {}; moved to failed/{}", batch.hide_file, reason, batch.id);
}

StationStore::Intake SpoolStore::take_hide(const ReadyScan& ready) {
  const auto settings = config();
  const std::string name = ready.scan.filename().string();
  BatchState batch;
  batch.id = spool_->new_batch_id();
  batch.created_at = utc_now_iso();
  batch.hide_file = name;
  batch.hide_sidecar = ready.sidecar.empty() ? "" : ready.sidecar.filename().string();
  const auto dir = spool_->batch_dir(batch.id);
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  // batch.json before the files: a crash in between leaves a batch that recovery abandons, and the
  // hide file still in the hides folder, taken again.
  Status claimed = error ? Status::failure("cannot create " + dir.string() + ": " + error.message())
                  : set_batch_stage(*spool_, batch, BatchStage::Nesting, "taking " + name + " into the spool",
                                    BatchLine::ByCaller)
                      ? Status::success()
                      : Status::failure("batch.json not written");
  if (claimed && !batch.hide_sidecar.empty()) claimed = move_durably(ready.sidecar, dir / batch.hide_sidecar);
  if (claimed) claimed = move_durably(ready.scan, dir / name);
  if (!claimed) {
    spdlog::error("hides folder: {} could not be taken into the spool: {}", name, claimed.error());
    return Intake::Taken;
  }
  HideFile hide;
  try {
    hide = read_hide_file(dir / name);
  } catch (const EngineError& failure) {
    fail_hide(batch, failure.what());
    return Intake::Taken;
  } catch (const std::exception& failure) {
    // A reader bug, not a refusal (nlohmann's type_error once escaped here and stopped the daemon): the
    // hide still goes to failed/ with the reason, and the daemon runs on.
    fail_hide(batch, name + ": unreadable hide file (" + failure.what() + ")");
    return Intake::Taken;
  }
  batch.hide_id = hide.hide_id;
  if (const std::string unknown = settle_hide_targets(hide.hide_id, hide.material, hide.cutter,
                                                      hide_sidecar_path(name).string(), *settings, batch.material,
                                                      batch.cutter);
      !unknown.empty()) {
    fail_hide(batch, unknown);
    return Intake::Taken;
  }
  if (!set_batch_stage(*spool_, batch, BatchStage::Nesting,
                       fmt::format("{}, {:.2f} m^2, lies on cutter {}; the computed jobs of {} are nested on it", name,
                                   hide.area_m2, batch.cutter, batch.material))) {
    fail_hide(batch, "hide " + hide.hide_id + ": batch.json not written");
    return Intake::Taken;
  }
  loaded_hides_.push_back({batch.id, Clock::now()});
  return Intake::Taken;
}

bool SpoolStore::computing_material(const std::string& material) const {
  for (const std::string& id : known_jobs_) {
    const auto state = spool_->read_state(JobFolder::Work, id);
    if (state && state->stage == JobStage::Claimed && state->ticket.material == material) return true;
  }
  return false;
}

void SpoolStore::nest_due_hides(Clock::time_point now) {
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
      const bool gone = !state || state->stage != JobStage::Computed || !state->stage_problem.empty();
      if (gone) hide_waiting_pieces_.erase(id);
      return gone;
    });
    const double waited_s = std::chrono::duration<double>(now - loaded->since).count();
    if (pool.empty() || !hide_is_due(pool.size(), computing_material(batch->material), waited_s, window_s)) {
      ++loaded;
      continue;
    }
    const std::size_t offered = std::min<std::size_t>(pool.size(), kHideMaxJobs);
    batch->job_ids.assign(pool.begin(), pool.begin() + static_cast<std::ptrdiff_t>(offered));
    pool.erase(pool.begin(), pool.begin() + static_cast<std::ptrdiff_t>(offered));
    const std::string note = fmt::format("nesting {} waiting job(s) of {} on cutter {}{}", batch->job_ids.size(),
                                         batch->material, batch->cutter,
                                         pool.empty() ? "" : " (" + std::to_string(pool.size()) + " wait for the next hide)");
    if (!set_batch_stage(*spool_, *batch, BatchStage::Nesting, note)) {
      // The jobs stay in the pool; the hide is offered again next turn.
      pool.insert(pool.begin(), batch->job_ids.begin(), batch->job_ids.end());
      ++loaded;
      continue;
    }
    to_nest(batch->id);
    loaded = loaded_hides_.erase(loaded);
  }
}

}  // namespace lastcut::daemon
