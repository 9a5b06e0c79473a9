#include "daemon/ledger_node/ledger_cut_store.hpp"

#include <spdlog/spdlog.h>

#include "daemon/ledger/ledger_connection.hpp"

namespace lastcut::daemon {

LedgerCutStore::LedgerCutStore(std::string cutter, const LedgerConfig& ledger, const SharedStore& shared,
                               ledger::LeaseKeeper& keeper, Pause pause, const LedgerJournal& journal)
    : cutter_(std::move(cutter)),
      ledger_(ledger),
      shared_(shared),
      keeper_(keeper),
      pause_(std::move(pause)),
      journal_(journal) {}

Result<std::optional<CutOrder>> LedgerCutStore::claim() {
  if (!client_) {
    auto connected = ledger::LedgerClient::connect(ledger_.url, ledger_.node);
    if (!connected) return connected.status();
    client_ = std::move(*connected);
  }
  auto batch = client_->claim_batch(ledger_.lease_s, cutter_);
  if (!batch) return batch.status();
  if (!batch->has_value()) return std::optional<CutOrder>{};
  claimed_ = std::move(**batch);
  keeper_.keep(claimed_->lease);
  const std::string id = std::to_string(claimed_->batch_id);
  return std::optional<CutOrder>{CutOrder{id, shared_.absolute(claimed_->cut_file), claimed_->cut_file,
                                          ("L" + id).substr(0, 16), claimed_->job_ids.size(), 0}};
}

bool LedgerCutStore::record(const std::function<Status()>& save, const LedgerJobChanges& changes) {
  const std::string label = "cutter " + cutter_ + ": batch " + std::to_string(claimed_->batch_id);
  const Status written = journal_.change_once_reachable(save_then(save, changes), pause_, keeper_.retry_s(), label);
  if (!written && !ledger::unreachable(written)) spdlog::error("{}: {}", label, written.error());
  return written.ok();
}

void LedgerCutStore::let_go() {
  keeper_.drop(claimed_->lease);
  claimed_.reset();
}

Status LedgerCutStore::mark_sending(const CutOrder& order) {
  if (!claimed_ || std::to_string(claimed_->batch_id) != order.batch_id) {
    return Status::failure("batch " + order.batch_id + " is not claimed by this node");
  }
  if (!record([&] { return client_->mark_sending(claimed_->lease); }, batch_job_changes(*claimed_, JobStage::Sending, ""))) {
    let_go();  // lost: whoever holds the batch now decides
    return Status::failure("the ledger did not take `sending` (the claim was lost or the node stops)");
  }
  return Status::success();
}

CutEnd LedgerCutStore::record_end(const CutOrder& order, CutEnd end, const std::string& reason,
                                  const std::vector<std::string>& /*cutter_answer: the ledger keeps no device log*/) {
  if (!claimed_ || std::to_string(claimed_->batch_id) != order.batch_id) {
    spdlog::error("cutter {}: batch {} is not claimed by this node; its end ({}) is not written", cutter_,
                  order.batch_id, to_string(end));
    return end;
  }
  switch (end) {
    case CutEnd::Cut:
      record([&] { return client_->mark_cut(claimed_->lease); }, batch_job_changes(*claimed_, JobStage::Cut, ""));
      break;
    case CutEnd::NotSent:
      record([&] { return client_->mark_not_sent(claimed_->lease, reason); }, {});
      break;
    case CutEnd::Held:
      record([&] { return client_->hold_batch(claimed_->lease, reason); },
             batch_job_changes(*claimed_, JobStage::Held, reason));
      break;
  }
  let_go();
  return end;
}

}  // namespace lastcut::daemon
