#include "daemon/station/compute_pool.hpp"

#include <algorithm>
#include <chrono>

#include <spdlog/spdlog.h>

#include "daemon/station/engine_steps.hpp"
#include "daemon/station/hide_policy.hpp"
#include "daemon/station/hide_step.hpp"

namespace lastcut::daemon {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// What a strip batch (BatchMade) and a hide (HideMade) both say.
template <typename Made>
void take_outcome(const Result<Made>& made, NestResult& result) {
  if (!made) {
    result.made = made.status();
    return;
  }
  result.rejected = made->rejected;
  result.cut_file = made->cut_file;
  result.pieces = made->piece_count;
  result.utilisation = made->utilisation;
}

// What the cutting room follows per material and hide, once the store has the nesting.
NestingStatus nesting_status(const NestWork& work, const NestResult& result) {
  NestingStatus status;
  status.material = work.material;
  status.hide = work.hide_name;
  status.batch = work.batch_dir.filename().string();
  status.cutter = work.cutter;
  status.pieces_placed = result.pieces;
  status.pieces_waiting = result.pieces_waiting;
  status.jobs_placed = static_cast<int>(result.placed.size());
  status.jobs_waiting = static_cast<int>(result.waiting.size());
  status.utilisation = result.utilisation;
  return status;
}

}  // namespace

ComputePool::ComputePool(ComputeStore& store, ProgressMonitor& monitor,
                         std::function<std::shared_ptr<const DaemonConfig>()> settings, ComputePoolTiming timing)
    : store_(store), monitor_(monitor), settings_(std::move(settings)), timing_(timing) {}

ComputePool::~ComputePool() { stop(); }

void ComputePool::start(int workers) {
  for (int i = 0; i < workers; ++i) {
    threads_.emplace_back([this, worker = "compute-" + std::to_string(i + 1)] { run(worker); });
  }
}

void ComputePool::wake() {
  {
    std::lock_guard lock(mutex_);
    ++wakes_;
  }
  wake_.notify_all();
}

void ComputePool::stop() {
  stopping_ = true;
  wake();
  for (std::thread& thread : threads_)
    if (thread.joinable()) thread.join();
  threads_.clear();
}

std::string ComputePool::trouble() const {
  std::lock_guard lock(mutex_);
  return trouble_;
}

void ComputePool::run(const std::string& worker) {
  while (!stopping_) {
    unsigned wakes_before = 0;
    {
      std::lock_guard lock(mutex_);
      wakes_before = wakes_;
    }
    if (turn(worker)) continue;
    std::unique_lock lock(mutex_);
    const double wait_s = trouble_.empty() ? timing_.idle_wait_s : timing_.retry_wait_s;
    // A wake() since this turn began counts: the work it announced may have come after the claim.
    wake_.wait_for(lock, std::chrono::duration<double>(wait_s),
                   [&] { return stopping_.load() || wakes_ != wakes_before; });
  }
}

bool ComputePool::turn(const std::string& worker) {
  Result<std::optional<ComputeClaim>> claimed = store_.claim(worker);
  if (!claimed) {
    note_trouble(claimed.error());
    return false;
  }
  note_trouble("");
  if (!*claimed) return false;
  if (auto* molds = std::get_if<std::unique_ptr<MoldsClaim>>(&**claimed)) {
    (*molds)->finish(compute_molds((*molds)->work(), worker));
  } else {
    NestClaim& nest = *std::get<std::unique_ptr<NestClaim>>(**claimed);
    const NestResult result = compute_nest(nest.work(), worker);
    nest.finish(result);
    if (observer_ && result.made && !result.cut_file.empty()) observer_->nesting_done(nesting_status(nest.work(), result));
  }
  return true;
}

void ComputePool::note_trouble(const std::string& trouble) {
  std::lock_guard lock(mutex_);
  if (trouble == trouble_) return;
  // Every worker meets the same trouble: the pool says it once, and once when it is over.
  if (trouble.empty()) spdlog::info("compute workers: the store answers again");
  else spdlog::warn("compute workers: {} (work waits and is retried; logged again when this changes)", trouble);
  trouble_ = trouble;
}

JobMolds ComputePool::compute_molds(const MoldsWork& work, const std::string& worker) {
  const auto settings = settings_();  // one configuration for the whole step (SIGHUP may replace it)
  return make_job_molds(work.scan, work.job_dir, work.ticket, *settings, monitor_, worker, "molds of " + work.label,
                        work.label);
}

NestResult ComputePool::compute_nest(const NestWork& work, const std::string& worker) {
  const auto settings = settings_();  // one configuration for the whole step (SIGHUP may replace it)
  NestResult result;
  const auto material = settings->materials.find(work.material);
  const auto cutter = settings->cutters.find(work.cutter);
  if (material == settings->materials.end()) {
    result.made = Status::failure("material " + work.material + " is not configured (any more)");
    return result;
  }
  if (cutter == settings->cutters.end()) {
    result.made = Status::failure("cutter " + work.cutter + " is not configured (any more)");
    return result;
  }
  const auto start = std::chrono::steady_clock::now();
  monitor_.begin(worker, "nesting " + work.label, settings->jobs.compute_timeout_s);
  if (work.hide_file.empty()) {
    std::vector<BatchJobInput> inputs;
    for (const NestJob& job : work.jobs)
      inputs.push_back({job.job_id, job_items_path(job.job_dir, work.material), job.copies});
    const Result<BatchMade> made = build_batch(inputs, material->second, cutter->second, settings->paths.machines_dir,
                                               settings->batch.nest_time_s, work.batch_dir);
    take_outcome(made, result);
  } else {
    std::vector<HideJobInput> inputs;
    for (std::size_t i = 0; i < work.jobs.size(); ++i) {
      const NestJob& job = work.jobs[i];
      inputs.push_back({job.job_id, job_items_path(job.job_dir, work.material), job.ticket.order,
                        hide_job_priority(job.ticket.priority, i, work.jobs.size()), job.copies,
                        job.ticket.split_over_hides});
    }
    const Result<HideMade> made = build_hide(inputs, work.batch_dir, work.hide_file, material->second, cutter->second,
                                             settings->paths.machines_dir, settings->batch.nest_time_s);
    take_outcome(made, result);
    if (made) result.waiting = made->waiting, result.pieces_waiting = made->pieces_waiting, result.split = made->split;
  }
  monitor_.end(worker);
  result.took_s = seconds_since(start);
  if (result.made && !result.cut_file.empty()) {
    for (const NestJob& job : work.jobs) {
      if (!result.rejected.contains(job.job_id) && !result.waiting.contains(job.job_id))
        result.placed.push_back(job.job_id);
    }
  }
  return result;
}

}  // namespace lastcut::daemon
