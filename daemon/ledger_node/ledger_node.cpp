// LedgerNode: opening and closing the node's store, the main loop's turn, and the small helpers its
// parts share. The parts: scan_intake.cpp, ledger_compute_store.cpp (the compute role's claims),
// ledger_station.cpp and ledger_cut_store.cpp (the cutters cabled here).
#include "daemon/ledger_node/ledger_node.hpp"

#include <spdlog/spdlog.h>

#include "daemon/ledger_node/orphan_sweep.hpp"

namespace lastcut::daemon {

LedgerNode::LedgerNode(const RunningConfig& config)
    : config_(config), ledger_(*config.get()->ledger), store_(ledger_.shared_dir) {}

LedgerNode::~LedgerNode() { close(); }

Status LedgerNode::open(const StationLinks& links) {
  links_ = links;
  const auto settings = config();  // one configuration for the whole step (SIGHUP may replace it)
  if (Status prepared = store_.prepare(); !prepared) return prepared;
  std::error_code error;
  std::filesystem::create_directories(settings->paths.spool_dir, error);
  if (error) return Status::failure("spool folder " + settings->paths.spool_dir.string() + ": " + error.message());

  auto connected = ledger::LedgerClient::connect(ledger().url, ledger().node);
  if (!connected) return connected.status();
  client_ = std::move(*connected);
  const auto migrated = client_->migrate();
  if (!migrated) return migrated.status();
  if (migrated->version_after != migrated->version_before) {
    spdlog::info("ledger schema migrated from version {} to {}", migrated->version_before, migrated->version_after);
  }
  std::vector<std::string> cutters;
  for (const auto& [name, section] : settings->cutters)
    if (ledger().owns_cutter(name)) cutters.push_back(name);
  journal_ = std::make_unique<LedgerJournal>(links_.observer);
  ledger::SweepOutcome registered;
  const Status opened = journal_->change([&]() -> Result<LedgerJobChanges> {
    auto outcome = client_->register_node(ledger().roles, cutters, settings->jobs.max_attempts);
    if (!outcome) return outcome.status();
    registered = std::move(*outcome);
    return held_job_changes(registered.jobs_held);
  });
  if (!opened) return opened;
  for (long long id : registered.batches_held)
    spdlog::error("batch {}: this node stopped while sending it: held for an operator, never re-sent", id);
  for (const ledger::HeldJob& job : registered.jobs_held)
    held_at_start_[job.cutter] = {job.cutter, "held", std::to_string(job.batch_id), job.reason, 0, 0, 0, 0};
  const std::size_t handed_back = registered.jobs_requeued.size() + registered.batches_requeued.size() +
                                  registered.batches_dissolved.size();
  if (handed_back) spdlog::warn("{} claim(s) of this node's previous run handed back to the queue", handed_back);

  keeper_ = std::make_unique<ledger::LeaseKeeper>(ledger().url, ledger().node, ledger().lease_s, ledger().heartbeat_s,
                                                  [](const std::string& line) { spdlog::warn("{}", line); });
  if (ledger().has_role("compute")) {
    compute_store_ = std::make_unique<LedgerComputeStore>(
        ledger(), store_, *keeper_, [this] { return config(); }, *journal_, [this](double seconds) {
          pause(seconds);
          return !stopping_.load();
        });
  }
  open_cutters(cutters);
  return Status::success();
}

void LedgerNode::tick(Clock::time_point now) {
  if (stopping_) return;
  if (now >= next_sweep_) {
    sweep();
    next_sweep_ = now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(ledger().heartbeat_s));
  }
  if (now >= next_orphan_sweep_) {
    // Orphans are rare and the shared folder may be large: once a minute is enough.
    const Result<std::vector<std::string>> removed = remove_orphan_batch_folders(*client_, store_, kOrphanGrace_s);
    note_trouble(orphan_trouble_, removed ? "" : removed.error(), "orphaned batch folders");
    next_orphan_sweep_ = now + std::chrono::minutes(1);
  }
}

std::string LedgerNode::where() const {
  std::string roles;
  for (const std::string& role : ledger().roles) roles += (roles.empty() ? "" : "+") + role;
  return "ledger node " + ledger().node + " (" + roles + "), shared folder " + store_.root().string();
}

std::string LedgerNode::status_line() const {
  return "ledger node " + ledger().node + ": " + std::to_string(entered_) + " scan(s) entered, " +
         std::to_string(duplicates_) + " duplicate(s), " + std::to_string(refused_) + " refused" +
         (keeper_ && !keeper_->reachable() ? "; ledger unreachable" : "");
}

void LedgerNode::stopping() {
  stopping_ = true;
  std::lock_guard lock(pause_mutex_);
  pause_wake_.notify_all();
}

void LedgerNode::close() {
  stopping();
  compute_store_.reset();
  cutters_.clear();
  keeper_.reset();  // kept leases simply run out; the next start of this node hands them back at once
}

void LedgerNode::pause(double seconds) {
  std::unique_lock lock(pause_mutex_);
  pause_wake_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return stopping_.load(); });
}

void LedgerNode::note_trouble(std::string& last, const std::string& now, const std::string& what) {
  if (now == last) return;
  const auto unreachable = [](const std::string& line) { return line.rfind("ledger unreachable", 0) == 0; };
  if (unreachable(now) || (now.empty() && unreachable(last))) {
    // Every thread meets the same outage: the node says it once, and once when it is over.
    std::lock_guard lock(ledger_condition_mutex_);
    if (unreachable(now) && !ledger_down_) spdlog::warn("{} (work waits and is retried; logged again when it is back)", now);
    if (now.empty() && ledger_down_) spdlog::info("ledger reachable again");
    ledger_down_ = !now.empty();
  } else if (now.empty()) {
    spdlog::info("{}: working again", what);
  } else {
    spdlog::warn("{}: {} (retrying; logged again when this changes)", what, now);
  }
  last = now;
}

}  // namespace lastcut::daemon
