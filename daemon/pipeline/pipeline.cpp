#include "daemon/pipeline/pipeline.hpp"

#include <unistd.h>

#include <spdlog/spdlog.h>

#include "engine/core/durable_file.hpp"

namespace lastcut::daemon {

Pipeline::Pipeline(std::shared_ptr<const DaemonConfig> config) : config_(std::move(config)) {}

Pipeline::~Pipeline() { stop(); }

std::shared_ptr<const DaemonConfig> Pipeline::config() const { return config_.get(); }

Status Pipeline::start() {
  const auto settings = config();
  spool_ = std::make_unique<Spool>(settings->paths.spool_dir);
  if (Status prepared = spool_->prepare(); !prepared) return prepared;
  spool_->on_job_written([this, observer = observer_](const JobState& state) {
    if (has_ended(state.stage)) {
      std::lock_guard lock(ended_mutex_);
      ended_incoming_.insert(state.id);
    }
    if (observer) observer->job_changed(job_event_of(state));
  });
  for (const auto& [name, section] : settings->cutters) {
    Cutter& cutter = cutters_[name];
    cutter.store = std::make_unique<SpoolCutStore>(name, *spool_);
    cutter.worker = std::make_unique<CutterWorker>(name, *cutter.store, monitor_, [this, name = name] {
      const auto current = config();
      const auto it = current->cutters.find(name);
      return it != current->cutters.end() ? it->second : CutterSection{};
    });
    if (observer_) {
      cutter.worker->on_status([observer = observer_](const CutterStatus& status) { observer->cutter_changed(status); });
    }
  }
  index_hashes();
  recover();
  hot_folder_ = std::make_unique<HotFolder>(settings->paths.watch_dir, settings->watch);
  if (Status watching = hot_folder_->start(); !watching) return watching;
  if (!settings->paths.hides_dir.empty()) {
    hide_folder_ = std::make_unique<HotFolder>(settings->paths.hides_dir, settings->watch, HotFolderContent::Hides);
    if (Status watching = hide_folder_->start(); !watching) return watching;
    spdlog::info("hides folder {} ({})", settings->paths.hides_dir.string(), hide_folder_->mode_description());
  }
  for (auto& [name, cutter] : cutters_) cutter.worker->start(CutterStatus{name, "idle", "", "", 0, 0, 0, 0});
  for (int i = 0; i < settings->jobs.compute_workers; ++i) workers_.emplace_back([this, i] { compute_worker(i + 1); });
  spdlog::info("watching {} ({}); spool {}; {} cutter(s); duplicates: {}", settings->paths.watch_dir.string(),
               hot_folder_->mode_description(), settings->paths.spool_dir.string(), cutters_.size(),
               to_string(settings->jobs.duplicate_policy));
  return Status::success();
}

void Pipeline::tick(Clock::time_point now) {
  for (const ReadyScan& ready : hot_folder_->collect_ready(now)) take(ready);
  if (hide_folder_)
    for (const ReadyScan& ready : hide_folder_->collect_ready(now)) take_hide(ready);
  std::vector<std::string> computed;
  {
    std::lock_guard lock(computed_mutex_);
    computed.swap(computed_);
  }
  for (const std::string& id : computed) {
    auto state = spool_->read_state(JobFolder::Work, id);
    if (state && state->stage == JobStage::Computed && state->stage_problem.empty()) add_to_batcher(*state);
  }
  close_due_batches(now, false);
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

void Pipeline::write_status_file() {
  nlohmann::json cutters = nlohmann::json::object();
  for (const auto& [name, cutter] : cutters_) {
    cutters[name] = {{"condition", cutter.worker->condition()}, {"queued_batches", cutter.store->queued()}};
  }
  const std::size_t waiting = strip_waiting_.size();
  nlohmann::json waiting_for_hide = nlohmann::json::object();
  for (const auto& [material, ids] : hide_waiting_)
    if (!ids.empty()) waiting_for_hide[material] = ids.size();
  const nlohmann::json status{{"pid", static_cast<long>(::getpid())},
                              {"updated_at", utc_now_iso()},
                              {"watch_folder", config()->paths.watch_dir.string()},
                              {"files_being_checked", hot_folder_ ? hot_folder_->pending_count() : 0},
                              {"to_compute", tasks_.size()},
                              {"waiting_for_batch", waiting},
                              {"waiting_for_hide", waiting_for_hide},
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

std::string Pipeline::status_line() const {
  const std::size_t waiting = strip_waiting_.size();
  std::string line = std::to_string(known_jobs_.size()) + " job(s) in work, " + std::to_string(tasks_.size()) +
                     " to compute, " + std::to_string(waiting) + " waiting for a batch";
  for (const auto& [name, cutter] : cutters_) {
    line += "; " + name + ": " + cutter.worker->condition();
    if (cutter.store->queued() > 0) line += ", " + std::to_string(cutter.store->queued()) + " batch(es) queued";
  }
  return line;
}

std::string Pipeline::reload(std::shared_ptr<const DaemonConfig> next) {
  return config_.reload(*next);
}

void Pipeline::stop() {
  if (!spool_) return;
  tasks_.clear_and_close();
  for (auto& worker : workers_) {
    if (worker.joinable()) worker.join();
  }
  workers_.clear();
  const double grace_s = config()->jobs.stop_grace_s;
  // In parallel: each cutter gets the whole grace time for the cut in its hands.
  std::vector<std::thread> stopping;
  for (auto& [name, cutter] : cutters_) {
    stopping.emplace_back([&worker = *cutter.worker, grace_s] { worker.stop(grace_s); });
  }
  for (auto& thread : stopping) thread.join();
  cutters_.clear();
  {
    // A stopped daemon says so: status must not show a stale "running".
    std::error_code error;
    std::filesystem::remove(spool_->root() / "status.json", error);
  }
  hot_folder_.reset();
  hide_folder_.reset();
  spool_.reset();
}

}  // namespace lastcut::daemon
