#include "daemon/station/cutter_worker.hpp"

#include <spdlog/spdlog.h>

#include "daemon/station/watched_send.hpp"

namespace lastcut::daemon {
namespace {

// With nothing queued the worker sleeps this long unless woken; a store that cannot tell whether
// work waits (a ledger shared with other nodes) is asked again after kPollNothing_s.
constexpr double kIdleWait_s = 1.0;
constexpr double kPollNothing_s = 0.25;

}  // namespace

std::string to_string(CutEnd end) {
  switch (end) {
    case CutEnd::Cut: return "cut";
    case CutEnd::NotSent: return "not sent";
    case CutEnd::Held: return "held";
  }
  return "held";
}

CutEnd cut_end_of(drivers::SendOutcome outcome) {
  switch (outcome) {
    case drivers::SendOutcome::Done: return CutEnd::Cut;
    case drivers::SendOutcome::Failed: return CutEnd::NotSent;      // the driver guarantees nothing was sent
    case drivers::SendOutcome::Interrupted: return CutEnd::Held;    // maybe partly cut: never again by itself
  }
  return CutEnd::Held;  // an outcome this code does not know: the safe side
}

void stop_cutter_workers(const std::vector<CutterWorker*>& workers, double grace_s) {
  std::vector<std::thread> stopping;
  for (CutterWorker* worker : workers) stopping.emplace_back([worker, grace_s] { worker->stop(grace_s); });
  for (std::thread& thread : stopping) thread.join();
}

CutterWorker::CutterWorker(std::string cutter, CutStore& store, ProgressMonitor& monitor,
                           std::function<CutterSection()> settings)
    : cutter_(std::move(cutter)), store_(store), monitor_(monitor), settings_(std::move(settings)) {}

CutterWorker::~CutterWorker() {
  if (thread_.joinable()) stop(0);
}

void CutterWorker::start(const CutterStatus& first) {
  reported_state_ = first.state;
  if (status_listener_) status_listener_(first);
  thread_ = std::thread([this] { run(); });
}

void CutterWorker::wake() {
  {
    std::lock_guard lock(mutex_);
    woken_ = true;
  }
  wake_.notify_all();
}

void CutterWorker::stop(double grace_s) {
  stopping_ = true;
  {
    std::unique_lock lock(mutex_);
    wake_.notify_all();
    if (!wake_.wait_for(lock, std::chrono::duration<double>(grace_s), [this] { return !sending_; })) {
      spdlog::warn("cutter {}: stopping; the cut in progress is interrupted and its batch held", cutter_);
    }
    // Also when no cut runs: a turn between its probe and its first byte must not start a whole cut
    // now (cancelled before the first byte, the driver reports nothing sent: queued again).
    cancel_ = true;
  }
  if (thread_.joinable()) thread_.join();
}

std::string CutterWorker::condition() const {
  std::lock_guard lock(mutex_);
  return condition_;
}

bool CutterWorker::cutting() const {
  std::lock_guard lock(mutex_);
  return sending_;
}

void CutterWorker::set_condition(const std::string& condition) {
  std::lock_guard lock(mutex_);
  condition_ = condition;
}

void CutterWorker::run() {
  while (!stopping_) {
    const double wait_s = turn();
    std::unique_lock lock(mutex_);
    wake_.wait_for(lock, std::chrono::duration<double>(wait_s), [this] { return stopping_.load() || woken_; });
    woken_ = false;
  }
}

double CutterWorker::turn() {
  if (paused()) return kIdleWait_s;
  const std::optional<std::string> next = store_.next_batch();
  if (!next) return kIdleWait_s;
  const CutterSection section = settings_();
  const drivers::ProbeResult probe = drivers::probe_cutter({section.link, cutter_, ""});
  if (!probe.ready) {
    note_cutter_problem(probe.reason.empty() ? probe.state : probe.reason, probe.state, *next, section.retry_interval_s);
    return section.retry_interval_s;
  }
  note_cutter_problem("", probe.state, *next, section.retry_interval_s);
  if (stopping_) return 0;  // no new claim while stopping
  if (paused()) return kIdleWait_s;  // paused during the probe
  const Result<std::optional<CutOrder>> claimed = store_.claim();
  note_store_trouble(claimed ? "" : claimed.error());
  if (!claimed) return section.retry_interval_s;
  if (!claimed->has_value()) return kPollNothing_s;
  return cut(**claimed, section) ? 0 : section.retry_interval_s;
}

bool CutterWorker::cut(const CutOrder& order, const CutterSection& section) {
  const std::string label = "cutter " + cutter_ + ": batch " + order.batch_id;
  const std::optional<std::string> program = read_cut_program(order.cut_file);
  if (!program) {
    const std::string reason = "the cut file " + order.cut_file_name + " is missing or empty";
    spdlog::error("{}: held: {}", label, reason);
    store_.record_end(order, CutEnd::Held, reason, {});
    report("held", order.batch_id, reason);
    return true;
  }
  if (Status marked = store_.mark_sending(order); !marked) {
    spdlog::error("{}: not sent, its state `sending` could not be written: {}", label, marked.error());
    return false;
  }
  {
    std::lock_guard lock(mutex_);
    sending_ = true;
  }
  set_condition("cutting " + order.batch_id);
  report("sending", order.batch_id, "", drivers::SendProgress{.bytes_total = program->size()});
  spdlog::info("{}: cutting ({} jobs{})", label, order.jobs,
               order.pieces > 0 ? ", " + std::to_string(order.pieces) + " pieces" : "");
  const auto progress = [&](const drivers::SendProgress& step) {
    if (step.bytes_total > 0) {
      set_condition("cutting " + order.batch_id + " (" + std::to_string(100 * step.bytes_sent / step.bytes_total) +
                    " %)");
    }
    report("sending", order.batch_id, "", step);
  };
  const drivers::SendResult result =
      send_watched(monitor_, "cutter " + cutter_, "batch " + order.batch_id,
                   {section.link, cutter_, order.job_name.substr(0, 16)}, *program, progress, cancel_);
  {
    std::lock_guard lock(mutex_);
    sending_ = false;
    wake_.notify_all();
  }
  CutEnd end = cut_end_of(result.outcome);
  std::string reason = result.reason;
  if (end == CutEnd::Held) {
    reason = "cutter " + cutter_ + " stopped while cutting batch " + order.batch_id + ": " + result.reason +
             "; pieces may be partly cut";
  }
  if (end == CutEnd::Cut) reason.clear();
  end = store_.record_end(order, end, reason, result.device_log);
  if (end != CutEnd::NotSent) refusal_.clear();
  switch (end) {
    case CutEnd::Cut:
      spdlog::info("{}: cut", label);
      set_condition("idle");
      report("idle", "", "");
      return true;
    case CutEnd::NotSent:
      // Nothing reached the machine: the batch waits in the queue and this cutter is retried.
      set_condition("waiting: " + reason);
      report("waiting", order.batch_id, reason);
      if (reason != refusal_) {
        spdlog::warn("{}: not started ({}); back in the queue, retrying every {} s", label, reason,
                     section.retry_interval_s);
        refusal_ = reason;
      }
      return false;
    case CutEnd::Held:
      if (cut_end_of(result.outcome) == CutEnd::NotSent) {
        reason = "cutter " + cutter_ + " refused batch " + order.batch_id + " before cutting (" + result.reason +
                 "), and its return to the queue could not be written";
      }
      spdlog::error("{}: held: {}", label, reason);
      set_condition("idle");
      report("held", order.batch_id, reason);
      return true;
  }
  return true;
}

bool CutterWorker::paused() {
  const std::optional<std::string> by = pauses_ ? pauses_->paused_by(cutter_) : std::nullopt;
  if (by) {
    const std::string reason = "paused by " + *by + "; its batches wait until it is resumed";
    set_condition(reason);
    if (reported_state_ != "paused") {
      spdlog::info("cutter {}: {}", cutter_, reason);
      report("paused", "", reason);
    }
    return true;
  }
  if (reported_state_ == "paused") {
    spdlog::info("cutter {}: resumed", cutter_);
    set_condition("idle");
    report("idle", "", "");
  }
  return false;
}

void CutterWorker::note_cutter_problem(const std::string& problem, const std::string& state,
                                       const std::string& next_batch, double retry_s) {
  if (!problem.empty()) {
    set_condition("waiting: " + problem);
    if (reported_state_ != "waiting" || problem != cutter_problem_) report("waiting", next_batch, problem);
    if (problem != cutter_problem_) {
      spdlog::warn("cutter {}: not ready ({}); its batches wait, retrying every {} s", cutter_, problem, retry_s);
    }
  } else if (!cutter_problem_.empty()) {
    spdlog::info("cutter {}: ready again ({})", cutter_, state);
    set_condition("idle");
    if (reported_state_ == "waiting") report("idle", "", "");
  }
  cutter_problem_ = problem;
}

void CutterWorker::note_store_trouble(const std::string& trouble) {
  if (trouble == store_trouble_) return;
  if (trouble.empty()) spdlog::info("cutter {}: its batches can be claimed again", cutter_);
  else spdlog::warn("cutter {}: {} (its batches wait; logged again when this changes)", cutter_, trouble);
  store_trouble_ = trouble;
}

void CutterWorker::report(const std::string& state, const std::string& batch_id, const std::string& reason,
                          const drivers::SendProgress& progress) {
  reported_state_ = state;
  if (!status_listener_) return;
  status_listener_(CutterStatus{cutter_, state, batch_id, reason, progress.lines_acked, progress.lines_total,
                                progress.bytes_sent, progress.bytes_total});
}

}  // namespace lastcut::daemon
