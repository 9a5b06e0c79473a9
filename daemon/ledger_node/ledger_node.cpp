// LedgerNode: start and stop in one readable order, the main loop's turn, and the small helpers the
// roles share. The roles themselves: scan_intake.cpp, ledger_compute.cpp, ledger_station.cpp.
#include "daemon/ledger_node/ledger_node.hpp"

#include <spdlog/spdlog.h>

namespace lastcut::daemon {

LedgerNode::LedgerNode(std::shared_ptr<const DaemonConfig> config)
    : ledger_(*config->ledger), config_(std::move(config)), store_(ledger_.shared_dir) {}

LedgerNode::~LedgerNode() { stop(); }

Status LedgerNode::start() {
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
  const auto registered = client_->register_node(ledger().roles, cutters, settings->jobs.max_attempts);
  if (!registered) return registered.status();
  for (long long id : registered->batches_held)
    spdlog::error("batch {}: this node stopped while sending it: held for an operator, never re-sent", id);
  for (const ledger::HeldJob& job : registered->jobs_held) {
    job_changed(job.job_id, job.scan_name, job.ticket, job.batch_id, JobStage::Held, job.reason);
    held_at_start_[job.cutter] = {job.cutter, "held", std::to_string(job.batch_id), job.reason, 0, 0, 0, 0};
  }
  const std::size_t handed_back = registered->jobs_requeued.size() + registered->batches_requeued.size() +
                                  registered->batches_dissolved.size();
  if (handed_back) spdlog::warn("{} claim(s) of this node's previous run handed back to the queue", handed_back);

  keeper_ = std::make_unique<ledger::LeaseKeeper>(ledger().url, ledger().node, ledger().lease_s, ledger().heartbeat_s,
                                                  [](const std::string& line) { spdlog::warn("{}", line); });
  scans_.folder = std::make_unique<HotFolder>(settings->paths.watch_dir, settings->watch);
  if (Status watching = scans_.folder->start(); !watching) return watching;
  if (!settings->paths.hides_dir.empty()) {
    hides_.folder = std::make_unique<HotFolder>(settings->paths.hides_dir, settings->watch, HotFolderContent::Hides);
    if (Status watching = hides_.folder->start(); !watching) return watching;
    spdlog::info("hides folder {} ({}): hides entered here lie on their cutter's table", settings->paths.hides_dir.string(),
                 hides_.folder->mode_description());
  }
  if (ledger().has_role("compute")) {
    for (int i = 0; i < settings->jobs.compute_workers; ++i) threads_.emplace_back([this, i] { compute_worker(i + 1); });
  }
  start_cutters(cutters);
  std::string roles;
  for (const std::string& role : ledger().roles) roles += (roles.empty() ? "" : "+") + role;
  spdlog::info("ledger node {} ({}): watching {} ({}), shared folder {}, {} cutter(s) cabled here", ledger().node,
               roles, settings->paths.watch_dir.string(), scans_.folder->mode_description(),
               store_.root().string(), cutters.size());
  return Status::success();
}

void LedgerNode::tick(Clock::time_point now) {
  if (stopping_) return;
  for (Intake* intake : {&scans_, &hides_}) {
    if (!intake->folder || now < intake->next) continue;
    for (const ReadyScan& ready : intake->folder->collect_ready(now)) {
      take(ready, *intake);
      if (intake->next > now) break;  // the ledger is away: the rest wait too
    }
  }
  if (now >= next_sweep_) {
    sweep();
    next_sweep_ = now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(ledger().heartbeat_s));
  }
}

std::string LedgerNode::status_line() const {
  return "ledger node " + ledger().node + ": " + std::to_string(entered_) + " scan(s) entered, " +
         std::to_string(duplicates_) + " duplicate(s), " + std::to_string(refused_) + " refused; " +
         std::to_string(cuts_in_progress()) + " cut(s) in progress" +
         (keeper_ && !keeper_->reachable() ? "; ledger unreachable" : "");
}

std::string LedgerNode::reload(std::shared_ptr<const DaemonConfig> next) {
  return config_.reload(*next);
}

void LedgerNode::stop() {
  if (stopping_.exchange(true)) return;
  {
    std::lock_guard lock(pause_mutex_);
    pause_wake_.notify_all();
  }
  stop_cutters();
  for (std::thread& thread : threads_)
    if (thread.joinable()) thread.join();
  threads_.clear();
  keeper_.reset();  // kept leases simply run out; the next start of this node hands them back at once
}

bool LedgerNode::connect_worker(std::unique_ptr<ledger::LedgerClient>& client, std::string& trouble,
                                const std::string& worker) {
  if (client) return true;
  auto connected = ledger::LedgerClient::connect(ledger().url, ledger().node);
  if (!connected) {
    note_trouble(trouble, connected.error(), worker);
    pause(ledger().heartbeat_s);
    return false;
  }
  client = std::move(*connected);
  return true;
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

Result<JobTicket> ticket_from_ledger(const std::string& text) {
  try {
    return ticket_from_json(nlohmann::json::parse(text));
  } catch (const std::exception& error) {
    return Status::failure("the job's ticket in the ledger is unreadable: " + std::string(error.what()));
  }
}

void LedgerNode::job_changed(long long job_id, const std::string& scan_name, const std::string& ticket_json,
                             long long batch_id, JobStage stage, const std::string& reason, const std::string& note) {
  const std::string label = "job " + std::to_string(job_id) + " (" + scan_name + ")";
  const std::string& text = reason.empty() ? note : reason;
  if (stage == JobStage::Failed) {
    spdlog::error("{}: failed: {}", label, text);
  } else if (stage == JobStage::Held) {
    spdlog::warn("{}: held: {} (after checking, `lastcut requeue {}`)", label, text, job_id);
  } else if (!text.empty()) {
    spdlog::info("{}: {}", label, text);
  }
  if (!observer_) return;
  JobEvent event;
  event.job_id = std::to_string(job_id);
  event.scan_name = scan_name;
  if (Result<JobTicket> ticket = ticket_from_ledger(ticket_json)) {
    event.order = ticket->order;
    event.material = ticket->material;
    event.cutter = ticket->cutter;
  }
  event.batch_id = batch_id ? std::to_string(batch_id) : "";
  event.stage = stage;
  event.reason = reason;
  event.at = utc_now_iso();
  observer_->job_changed(event);
}

void LedgerNode::batch_event(const ledger::BatchClaim& claim, JobStage stage, const std::string& reason) {
  for (std::size_t i = 0; i < claim.job_ids.size(); ++i) {
    job_changed(claim.job_ids[i], claim.job_names[i], claim.job_tickets[i], claim.batch_id, stage, reason);
  }
}

}  // namespace lastcut::daemon
