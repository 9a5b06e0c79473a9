#include "daemon/spool_store/spool_store.hpp"

#include <unistd.h>

#include <spdlog/spdlog.h>

#include "engine/core/durable_file.hpp"

namespace lastcut::daemon {

std::shared_ptr<const DaemonConfig> SpoolStore::config() const { return config_.get(); }

Status SpoolStore::open(const StationLinks& links) {
  links_ = links;
  const auto settings = config();
  spool_ = std::make_unique<Spool>(settings->paths.spool_dir);
  if (Status prepared = spool_->prepare(); !prepared) return prepared;
  spool_->on_job_written([this, observer = links_.observer](const JobState& state) {
    if (has_ended(state.stage)) {
      std::lock_guard lock(ended_mutex_);
      ended_incoming_.insert(state.id);
    }
    if (observer) observer->job_changed(job_event_of(state));
  });
  // Jobs computed, and jobs whose next part waits, are handed to the batcher on the main thread (tick).
  const auto computed = [this](const std::string& job_id) {
    std::lock_guard lock(computed_mutex_);
    computed_.push_back(job_id);
  };
  for (const auto& [name, section] : settings->cutters)
    cutters_[name] = std::make_unique<SpoolCutStore>(name, *spool_, computed);
  compute_store_ = std::make_unique<SpoolComputeStore>(
      *spool_, [this] { return config(); },
      SpoolComputeStore::Listeners{computed, [this](const BatchState& batch) { enqueue_batch(batch); }});
  index_hashes();
  recover();
  return Status::success();
}

std::vector<StationCutter> SpoolStore::cutters() {
  std::vector<StationCutter> places;
  for (const auto& [name, store] : cutters_) places.push_back({name, store.get(), {name, "idle", "", "", 0, 0, 0, 0}});
  return places;
}

void SpoolStore::tick(Clock::time_point now) {
  std::vector<std::string> computed;
  {
    std::lock_guard lock(computed_mutex_);
    computed.swap(computed_);
  }
  for (const std::string& id : computed) {
    auto state = spool_->read_state(JobFolder::Work, id);
    if (state && state->stage == JobStage::Computed && state->stage_problem.empty()) add_to_batcher(*state);
  }
  close_due_batches(now);
  nest_due_hides(now);
  if (now >= next_work_scan_) {
    scan_work_folder();
    next_work_scan_ = now + std::chrono::seconds(1);
  }
  if (now >= next_status_file_) {
    write_status_file();
    next_status_file_ = now + std::chrono::seconds(2);
  }
}

void SpoolStore::to_compute(const std::string& job_id) {
  compute_store_->add_job(job_id);
  links_.wake_compute();
}

void SpoolStore::to_nest(const std::string& batch_id) {
  compute_store_->add_batch(batch_id);
  links_.wake_compute();
}

void SpoolStore::write_status_file() {
  nlohmann::json cutters = nlohmann::json::object();
  for (const auto& [name, store] : cutters_) {
    cutters[name] = {{"condition", links_.cutter_condition(name)}, {"queued_batches", store->queued()}};
  }
  const std::size_t waiting = strip_batcher_.waiting();
  nlohmann::json waiting_for_hide = nlohmann::json::object(), pieces_waiting_for_hide = nlohmann::json::object();
  for (const auto& [material, ids] : hide_waiting_) {
    if (ids.empty()) continue;
    waiting_for_hide[material] = ids.size();
    long long pieces = 0;
    for (const std::string& id : ids) pieces += hide_waiting_pieces_.contains(id) ? hide_waiting_pieces_.at(id) : 0;
    pieces_waiting_for_hide[material] = pieces;
  }
  const nlohmann::json status{{"pid", static_cast<long>(::getpid())},
                              {"updated_at", utc_now_iso()},
                              {"watch_folder", config()->paths.watch_dir.string()},
                              {"files_being_checked", links_.files_being_checked()},
                              {"to_compute", compute_store_->waiting()},
                              {"waiting_for_batch", waiting},
                              {"waiting_for_hide", waiting_for_hide},
                              {"pieces_waiting_for_hide", pieces_waiting_for_hide},
                              {"cutters", cutters}};
  // Not fsync'ed on purpose: it is rewritten every 2 s and worthless after a crash.
  const Status written =
      write_file_durably(spool_->root() / "status.json", status.dump(2) + "\n", WriteSync::AtomicOnly);
  // Once per change, not every 2 s; `lastcut status` shows the last status written meanwhile.
  if (written.error() != status_file_error_) {
    if (!written) spdlog::error("status.json for `lastcut status` not written: {}", written.error());
    else spdlog::info("status.json for `lastcut status` written again");
    status_file_error_ = written.error();
  }
}

std::string SpoolStore::where() const { return "spool " + config()->paths.spool_dir.string(); }

std::string SpoolStore::status_line() const {
  std::size_t queued = 0;
  for (const auto& [name, store] : cutters_) queued += store->queued();
  return std::to_string(known_jobs_.size()) + " job(s) in work, " + std::to_string(compute_store_->waiting()) +
         " to compute, " + std::to_string(strip_batcher_.waiting()) + " waiting for a batch, " + std::to_string(queued) +
         " batch(es) queued";
}

void SpoolStore::close() {
  if (!spool_) return;
  compute_store_->clear();
  {
    // A stopped daemon says so: status must not show a stale "running".
    std::error_code error;
    std::filesystem::remove(spool_->root() / "status.json", error);
  }
  compute_store_.reset();
  cutters_.clear();
  spool_.reset();
}

}  // namespace lastcut::daemon
