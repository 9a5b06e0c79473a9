#include "daemon/pipeline/cutter_dispatcher.hpp"

#include <spdlog/spdlog.h>

#include "daemon/pipeline/job_outcomes.hpp"
#include "daemon/station/watched_send.hpp"
#include "drivers/cutter.hpp"

namespace lastcut::daemon {
namespace {

// Marks the batch and its jobs with `stage` on disk; false when the batch file cannot be written
// (the failure is logged and noted in its jobs' reports).
bool mark_batch(const Spool& spool, BatchState& batch, BatchStage stage, const std::string& note) {
  batch.stage = stage;
  batch.updated_at = utc_now_iso();
  if (Status written = spool.write_batch(batch); !written) {
    report_batch_problem(spool, batch, std::string(to_string(stage)) + " (" + note + "), but batch.json not written: " +
                                           written.error());
    return false;
  }
  // Job states follow only the sending / back-to-queued steps; the ends (cut, held) are written
  // by complete_batch_jobs / hold_batch_jobs together with the move out of work/.
  JobStage job_stage = JobStage::Batched;
  switch (stage) {
    case BatchStage::Queued: job_stage = JobStage::Batched; break;
    case BatchStage::Sending: job_stage = JobStage::Sending; break;
    case BatchStage::Nesting:
    case BatchStage::Cut:
    case BatchStage::Held:
    case BatchStage::Abandoned:
    case BatchStage::Empty: return true;
  }
  for (const std::string& id : batch.job_ids) {
    auto state = spool.read_state(JobFolder::Work, id);
    if (!state || state->batch_id != batch.id) continue;
    state->advance(job_stage, note);
    if (Status written = spool.write_state(JobFolder::Work, *state); !written) {
      report_job_problem(spool, JobFolder::Work, *state, "state not written: " + written.error());
    }
  }
  return true;
}

// The batch (with batch.reason) and its jobs go to held.
void hold_batch(const Spool& spool, BatchState& batch) {
  mark_batch(spool, batch, BatchStage::Held, batch.reason);
  hold_batch_jobs(spool, batch, batch.reason);
}

}  // namespace

CutterDispatcher::CutterDispatcher(std::string name, Spool& spool, ProgressMonitor& monitor,
                                   std::function<CutterSection()> settings)
    : name_(std::move(name)), spool_(spool), monitor_(monitor), settings_(std::move(settings)) {}

CutterDispatcher::~CutterDispatcher() {
  if (thread_.joinable()) stop(0);
}

void CutterDispatcher::start() { thread_ = std::thread([this] { run(); }); }

void CutterDispatcher::enqueue(const std::string& batch_id) { queue_.push(batch_id); }

std::string CutterDispatcher::condition() const {
  std::lock_guard lock(mutex_);
  return condition_;
}

void CutterDispatcher::set_condition(const std::string& condition) {
  std::lock_guard lock(mutex_);
  condition_ = condition;
}

void CutterDispatcher::report(const std::string& state, const std::string& batch_id, const std::string& reason,
                              const drivers::SendProgress& progress) {
  reported_state_ = state;
  if (!status_listener_) return;
  status_listener_(CutterStatus{name_, state, batch_id, reason, progress.lines_acked, progress.lines_total,
                                progress.bytes_sent, progress.bytes_total});
}

void CutterDispatcher::stop(double grace_s) {
  stopping_ = true;
  queue_.clear_and_close();
  {
    std::unique_lock lock(mutex_);
    wake_.notify_all();
    if (!wake_.wait_for(lock, std::chrono::duration<double>(grace_s), [this] { return !sending_; })) {
      spdlog::warn("cutter {}: stopping; the cut in progress is interrupted and its jobs held", name_);
      cancel_ = true;
    }
  }
  if (thread_.joinable()) thread_.join();
}

void CutterDispatcher::wait_before_retry(double seconds) {
  std::unique_lock lock(mutex_);
  wake_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return stopping_.load(); });
}

void CutterDispatcher::run() {
  while (auto batch_id = queue_.pop()) {
    while (!stopping_ && !cut_batch(*batch_id)) wait_before_retry(settings_().retry_interval_s);
    if (!stopping_) set_condition("idle");
    // A held batch stays the cutter's live state until the next one starts: the machine may
    // hold a partly cut hide.
    if (!stopping_ && reported_state_ != "held" && reported_state_ != "idle") report("idle", "", "");
  }
}

bool CutterDispatcher::cut_batch(const std::string& batch_id) {
  auto batch = spool_.read_batch(batch_id);
  // Finished or taken back meanwhile; a batch.json without a known stage is held by recovery.
  if (!batch || batch->stage != BatchStage::Queued || !batch->stage_problem.empty()) return true;
  const CutterSection section = settings_();
  const drivers::CutterConfig config{section.link, name_, batch_id.substr(0, 16)};

  const drivers::ProbeResult probe = drivers::probe_cutter(config);
  if (!probe.ready) {
    const std::string problem = probe.reason.empty() ? probe.state : probe.reason;
    set_condition("waiting: " + problem);
    if (reported_state_ != "waiting" || problem != last_problem_) report("waiting", batch_id, problem);
    if (problem != last_problem_) {
      spdlog::warn("cutter {}: not ready ({}); batch {} waits, retrying every {} s", name_, problem, batch_id,
                   section.retry_interval_s);
      last_problem_ = problem;
    }
    return false;
  }
  if (!last_problem_.empty()) spdlog::info("cutter {}: ready again ({})", name_, probe.state);
  last_problem_.clear();

  const std::optional<std::string> program = read_cut_program(spool_.batch_dir(batch_id) / batch->cut_file);
  if (!program) {
    batch->reason = "the cut file " + batch->cut_file + " is missing or empty";
    hold_batch(spool_, *batch);
    report("held", batch_id, batch->reason);
    return true;
  }

  // The point of no return: from here on a crash or fault means "maybe partly cut".
  if (!mark_batch(spool_, *batch, BatchStage::Sending, "sending to cutter " + name_)) return false;
  {
    std::lock_guard lock(mutex_);
    sending_ = true;
  }
  set_condition("cutting " + batch_id);
  report("sending", batch_id, "");
  spdlog::info("cutter {}: cutting batch {} ({} jobs, {} pieces)", name_, batch_id, batch->job_ids.size(),
               batch->piece_count);
  const auto progress = [&](const drivers::SendProgress& step) {
    if (step.bytes_total > 0) {
      set_condition("cutting " + batch_id + " (" + std::to_string(100 * step.bytes_sent / step.bytes_total) + " %)");
    }
    report("sending", batch_id, "", step);
  };
  const drivers::SendResult result =
      send_watched(monitor_, "cutter " + name_, "batch " + batch_id, config, *program, progress, cancel_);
  {
    std::lock_guard lock(mutex_);
    sending_ = false;
    wake_.notify_all();
  }
  batch->cutter_answer = result.device_log;
  switch (result.outcome) {
    case drivers::SendOutcome::Done:
      batch->reason.clear();
      // Cut, even if batch.json cannot say so: the jobs must reach done/, never be cut again.
      mark_batch(spool_, *batch, BatchStage::Cut, "the cutter reported the job finished");
      complete_batch_jobs(spool_, *batch);
      report("idle", "", "");
      return true;
    case drivers::SendOutcome::Failed:
      // The driver guarantees nothing reached the machine: the batch may wait and go again.
      batch->reason = result.reason;
      if (!mark_batch(spool_, *batch, BatchStage::Queued, "cutter refused before cutting: " + result.reason)) {
        // Still "sending" on disk, which recovery would hold: hold it now and say why.
        batch->reason = "cutter " + name_ + " refused batch " + batch_id + " before cutting (" + result.reason +
                        "), and its return to the queue could not be written";
        hold_batch(spool_, *batch);
        report("held", batch_id, batch->reason);
        return true;
      }
      set_condition("waiting: " + result.reason);
      report("waiting", batch_id, result.reason);
      if (result.reason != last_problem_) {
        spdlog::warn("cutter {}: batch {} not started ({}); retrying every {} s", name_, batch_id, result.reason,
                     section.retry_interval_s);
        last_problem_ = result.reason;
      }
      return stopping_.load();
    case drivers::SendOutcome::Interrupted:
      break;
  }
  batch->reason = "cutter " + name_ + " stopped while cutting batch " + batch_id + ": " + result.reason +
                  "; pieces may be partly cut";
  hold_batch(spool_, *batch);
  report("held", batch_id, batch->reason);
  return true;
}

}  // namespace lastcut::daemon
