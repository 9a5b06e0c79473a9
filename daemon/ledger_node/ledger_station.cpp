// The station role of a ledger node: one thread per cutter cabled here. It claims the cutter's
// oldest queued batch only when the cutter answers its probe, marks it `sending` before the first
// byte (fenced by the lease), sends exactly the cut file of the shared folder, then marks it cut,
// or held when the cut was interrupted (at most once: never sent again by itself), or queued again
// when the driver guarantees nothing reached the machine. A ledger away after a cut: the end is
// written again until it lands (the lease keeper renews the claim meanwhile).
#include <spdlog/spdlog.h>

#include "daemon/ledger_node/ledger_node.hpp"
#include "daemon/station/watched_send.hpp"
#include "drivers/cutter.hpp"

namespace lastcut::daemon {

void LedgerNode::station_worker(const std::string& cutter) {
  const std::string worker = "cutter " + cutter;
  const CutterSection section = config()->cutters.at(cutter);
  std::unique_ptr<ledger::LedgerClient> client;
  std::string trouble, cutter_trouble;
  // A batch this station was sending when it died stays the cutter's news until its next batch.
  const auto held = held_at_start_.find(cutter);
  report_cutter(held != held_at_start_.end() ? held->second : CutterStatus{cutter, "idle", "", "", 0, 0, 0, 0});
  while (!stopping_) {
    if (!connect_worker(client, trouble, worker)) continue;
    const drivers::ProbeResult probe = drivers::probe_cutter({section.link, cutter, ""});
    if (!probe.ready) {
      const std::string problem = probe.reason.empty() ? probe.state : probe.reason;
      if (problem != cutter_trouble) report_cutter({cutter, "waiting", "", problem, 0, 0, 0, 0});
      note_trouble(cutter_trouble, problem, worker + " (its batches wait in the ledger)");
      pause(section.retry_interval_s);
      continue;
    }
    if (!cutter_trouble.empty()) report_cutter({cutter, "idle", "", "", 0, 0, 0, 0});
    note_trouble(cutter_trouble, "", worker);
    const auto batch = client->claim_batch(ledger().lease_s, cutter);
    note_trouble(trouble, batch ? "" : batch.error(), worker);
    if (!batch || !batch->has_value()) {
      pause(batch ? 0.25 : ledger().heartbeat_s);
      continue;
    }
    keeper_->keep((*batch)->lease);
    const bool retry_later = !cut_batch(*client, **batch, section);
    keeper_->drop((*batch)->lease);
    if (retry_later) pause(section.retry_interval_s);
  }
}

bool LedgerNode::cut_batch(ledger::LedgerClient& client, const ledger::BatchClaim& claim, const CutterSection& section) {
  const std::string id = std::to_string(claim.batch_id);
  const std::string label = "cutter " + claim.cutter + ": batch " + id;
  // Writes the batch's end, again and again while the ledger is away; false when the lease is lost.
  const auto record = [&](const std::function<Status()>& change) {
    for (double wait_s = ledger().heartbeat_s;; wait_s = std::min(2 * wait_s, ledger().lease_s)) {
      const Status written = change();
      if (written) return true;
      if (written.error().rfind("ledger unreachable", 0) != 0) {
        spdlog::error("{}: {}", label, written.error());
        return false;
      }
      spdlog::warn("{}: the ledger is away, its state is written when it is back: {}", label, written.error());
      pause(wait_s);
      if (stopping_) return false;
    }
  };
  const std::optional<std::string> program = read_cut_program(store_.absolute(claim.cut_file));
  if (!program) {
    const std::string reason = "the cut file " + claim.cut_file + " is missing or empty in the shared folder";
    spdlog::error("{}: held: {}", label, reason);
    record([&] { return client.hold_batch(claim.lease, reason); });
    report_cutter({claim.cutter, "held", id, reason, 0, 0, 0, 0});
    return true;
  }
  // The point of no return: from here on a crash or fault means "maybe partly cut".
  if (!record([&] { return client.mark_sending(claim.lease); })) return true;
  spdlog::info("{}: cutting ({} jobs)", label, claim.job_ids.size());
  report_cutter({claim.cutter, "sending", id, "", 0, 0, 0, program->size()});
  batch_event(claim, JobStage::Sending, "");
  ++cuts_in_progress_;
  const auto progress = [&](const drivers::SendProgress& step) {
    report_cutter({claim.cutter, "sending", id, "", step.lines_acked, step.lines_total, step.bytes_sent,
                   step.bytes_total});
  };
  const drivers::SendResult result =
      send_watched(monitor_, "cutter " + claim.cutter, "batch " + id,
                   {section.link, claim.cutter, ("L" + id).substr(0, 16)}, *program, progress, cancel_cut_);
  --cuts_in_progress_;
  switch (result.outcome) {
    case drivers::SendOutcome::Done:
      spdlog::info("{}: cut", label);
      record([&] { return client.mark_cut(claim.lease); });
      batch_event(claim, JobStage::Cut, "");
      report_cutter({claim.cutter, "idle", "", "", 0, 0, 0, 0});
      return true;
    case drivers::SendOutcome::Failed:
      spdlog::warn("{}: not started ({}); back in the queue, retrying every {} s", label, result.reason,
                   section.retry_interval_s);
      record([&] { return client.mark_not_sent(claim.lease, result.reason); });
      report_cutter({claim.cutter, "waiting", id, result.reason, 0, 0, 0, 0});
      return false;
    case drivers::SendOutcome::Interrupted:
      break;
  }
  const std::string reason =
      "cutter " + claim.cutter + " stopped while cutting batch " + id + ": " + result.reason + "; pieces may be partly cut";
  spdlog::error("{}: held: {}", label, reason);
  record([&] { return client.hold_batch(claim.lease, reason); });
  batch_event(claim, JobStage::Held, reason);
  report_cutter({claim.cutter, "held", id, reason, 0, 0, 0, 0});
  return true;
}

void LedgerNode::report_cutter(const CutterStatus& status) {
  if (observer_) observer_->cutter_changed(status);
}

}  // namespace lastcut::daemon
