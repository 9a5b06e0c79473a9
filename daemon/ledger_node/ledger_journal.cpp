#include "daemon/ledger_node/ledger_journal.hpp"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "daemon/ledger/ledger_connection.hpp"

namespace lastcut::daemon {

LedgerJobChanges batch_job_changes(const ledger::BatchClaim& claim, JobStage stage, const std::string& reason) {
  LedgerJobChanges changes;
  for (std::size_t i = 0; i < claim.job_ids.size(); ++i)
    changes.push_back({claim.job_ids[i], claim.job_names[i], claim.job_tickets[i], claim.batch_id, stage, reason, ""});
  return changes;
}

LedgerJobChanges held_job_changes(const std::vector<ledger::HeldJob>& jobs) {
  LedgerJobChanges changes;
  for (const ledger::HeldJob& job : jobs)
    changes.push_back({job.job_id, job.scan_name, job.ticket, job.batch_id, JobStage::Held, job.reason, ""});
  return changes;
}

Result<JobTicket> ticket_from_ledger(const std::string& text) {
  try {
    return ticket_from_json(nlohmann::json::parse(text));
  } catch (const std::exception& error) {
    return Status::failure("the job's ticket in the ledger is unreadable: " + std::string(error.what()));
  }
}

LedgerJournal::Save save_then(std::function<Status()> call, LedgerJobChanges changes) {
  return [call = std::move(call), changes = std::move(changes)]() -> Result<LedgerJobChanges> {
    if (Status saved = call(); !saved) return saved;
    return changes;
  };
}

Status LedgerJournal::change(const Save& save) const {
  Result<LedgerJobChanges> saved = save();
  if (!saved) return saved.status();
  for (const LedgerJobChange& change : *saved) tell(change);
  return Status::success();
}

Status LedgerJournal::change_once_reachable(const Save& save, const Pause& pause, double retry_s,
                                            const std::string& label) const {
  bool waited = false;
  while (true) {
    const Status changed = change(save);
    if (!ledger::unreachable(changed)) {
      if (waited && changed) spdlog::info("{}: written in the ledger, now that it answers again", label);
      return changed;
    }
    if (!waited) spdlog::warn("{}: kept until the ledger answers again: {}", label, changed.error());
    waited = true;
    if (!pause(retry_s)) return changed;
  }
}

void LedgerJournal::tell(const LedgerJobChange& change) const {
  const std::string label = "job " + std::to_string(change.job_id) + " (" + change.scan_name + ")";
  const std::string& text = change.reason.empty() ? change.note : change.reason;
  if (change.stage == JobStage::Failed) {
    spdlog::error("{}: failed: {}", label, text);
  } else if (change.stage == JobStage::Held) {
    spdlog::warn("{}: held: {} (after checking, `lastcut requeue {}`)", label, text, change.job_id);
  } else if (!text.empty()) {
    spdlog::info("{}: {}", label, text);
  }
  if (!observer_) return;
  JobEvent event;
  event.job_id = std::to_string(change.job_id);
  event.scan_name = change.scan_name;
  if (Result<JobTicket> ticket = ticket_from_ledger(change.ticket_json)) {
    event.order = ticket->order;
    event.material = ticket->material;
    event.cutter = ticket->cutter;
  }
  event.batch_id = change.batch_id ? std::to_string(change.batch_id) : "";
  event.stage = change.stage;
  event.reason = change.reason;
  event.at = utc_now_iso();
  observer_->job_changed(event);
}

}  // namespace lastcut::daemon
