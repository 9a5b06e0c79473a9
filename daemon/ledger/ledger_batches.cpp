// The batch half of the ledger queue: computed jobs grouped per cutter and material and nested by
// a compute node, claimed by the station that owns the cutter, marked sending before the first byte, then cut or held.
#include <algorithm>

#include <pqxx/pqxx>

#include "daemon/ledger/ledger_transaction.hpp"

namespace lastcut::ledger {
namespace {

Status batch_in(pqxx::work& tx, long long batch_id, const std::string& expected) {
  const std::string state =
      tx.exec_params1("SELECT state FROM batches WHERE id = $1 FOR UPDATE", batch_id)[0].as<std::string>();
  if (state != expected) {
    return Status::failure("batch " + std::to_string(batch_id) + " is " + state + ", not " + expected);
  }
  return Status::success();
}

std::vector<long long> jobs_of(pqxx::work& tx, long long batch_id) {
  std::vector<long long> ids;
  for (const pqxx::row& r : tx.exec_params("SELECT id FROM jobs WHERE batch_id = $1 ORDER BY id", batch_id)) {
    ids.push_back(r[0].as<long long>());
  }
  return ids;
}

}  // namespace

// The batch's jobs, their scans and tickets into `claim`, ascending (the hide's too, for a hide batch).
void fill_jobs(pqxx::work& tx, BatchClaim& claim) {
  for (const pqxx::row& r : tx.exec_params(
           "SELECT id, scan_sha256, scan_name, ticket, coalesce(duplicate_of, 0), parts::text, part FROM jobs"
           " WHERE batch_id = $1 ORDER BY id",
           claim.batch_id)) {
    claim.job_ids.push_back(r[0].as<long long>());
    claim.job_folders.push_back(job_folder_name(r[1].as<std::string>(), r[0].as<long long>(), r[4].as<long long>()));
    claim.job_names.push_back(r[2].as<std::string>());
    claim.job_tickets.push_back(r[3].as<std::string>());
    claim.job_parts.push_back(daemon::parts_from_json(nlohmann::json::parse(r[5].as<std::string>(), nullptr, false)));
    claim.job_part.push_back(r[6].as<int>());
  }
  const pqxx::result hide = tx.exec_params(
      "SELECT h.id, h.name, h.hide_file FROM batches b JOIN hides h ON h.id = b.hide_id WHERE b.id = $1",
      claim.batch_id);
  if (hide.empty()) return;
  claim.hide_id = hide[0][0].as<long long>();
  claim.hide_name = hide[0][1].as<std::string>();
  claim.hide_file = hide[0][2].as<std::string>();
}


Result<std::optional<BatchClaim>> LedgerClient::make_batch(const BatchChooser& choose, double lease_s,
                                                           const std::vector<std::string>& hide_materials) {
  using Claim = std::optional<BatchClaim>;
  return transact<Claim>("making a batch", [&](pqxx::work& tx) -> Result<Claim> {
    std::vector<ComputedJob> waiting;
    for (const pqxx::row& r : tx.exec_params(
             "SELECT id, material, cutter, pieces, extract(epoch FROM now() - updated_at) FROM jobs"
             " WHERE state = 'computed' AND material <> ALL($1::text[]) ORDER BY updated_at, id"
             " FOR UPDATE SKIP LOCKED",
             text_array(hide_materials))) {
      waiting.push_back({r[0].as<long long>(), r[1].as<std::string>(), r[2].as<std::string>(), r[3].as<int>(),
                         r[4].as<double>()});
    }
    const std::vector<long long> ids = waiting.empty() ? std::vector<long long>{} : choose(waiting);
    if (ids.empty()) return Claim();
    BatchClaim claim;
    std::size_t offered = 0;
    for (const ComputedJob& job : waiting) {
      if (std::find(ids.begin(), ids.end(), job.job_id) == ids.end()) continue;
      if (offered++ == 0) claim.cutter = job.cutter, claim.material = job.material;
      if (job.cutter != claim.cutter || job.material != claim.material)
        return Status::failure("the batching rule mixed cutters or materials in one batch");
    }
    if (offered != ids.size()) return Status::failure("the batching rule chose jobs that were not offered");
    claim.batch_id =
        tx.exec_params1(
              "INSERT INTO batches (cutter, material, state, created_by) VALUES ($1, $2, 'nesting', $3) RETURNING id",
              claim.cutter, claim.material, node_)[0]
            .as<long long>();
    tx.exec_params("UPDATE jobs SET state = 'batched', batch_id = $1, updated_at = now() WHERE id = ANY($2::bigint[])",
                   claim.batch_id, id_array(ids));
    fill_jobs(tx, claim);
    for (long long id : claim.job_ids) {
      add_event(tx, id, node_, "batched", "batch " + std::to_string(claim.batch_id) + " for " + claim.cutter);
    }
    claim.lease = {LeaseKind::Batch, claim.batch_id, take_lease(tx, node_, LeaseKind::Batch, claim.batch_id, lease_s)};
    return Claim(std::move(claim));
  });
}

Status LedgerClient::mark_nested(const Lease& lease, const NestedBatch& nested) {
  return transact<bool>("marking batch " + std::to_string(lease.object_id) + " nested",
                        [&](pqxx::work& tx) -> Result<bool> {
                          if (Status held = check_lease(tx, node_, lease); !held) return held;
                          if (Status nesting = batch_in(tx, lease.object_id, "nesting"); !nesting) return nesting;
                          // Jobs leaving the batch: rejected ones fail, the ones a hide had no room for wait again,
                          // those of a batch that could not be made at all are held for an operator.
                          const auto leave = [&](const auto& jobs, const char* state, const char* event) {
                            for (const auto& [job_id, reason] : jobs) {
                              tx.exec_params(
                                  "UPDATE jobs SET state = $4, batch_id = NULL, reason = $3, updated_at = now()"
                                  " WHERE id = $1 AND batch_id = $2",
                                  job_id, lease.object_id, reason, state);
                              add_event(tx, job_id, node_, event, reason);
                            }
                          };
                          // A job the hide took in part cuts that part now; the rest is its next part.
                          for (const NestedBatch::Split& split : nested.split) {
                            tx.exec_params(
                                "UPDATE jobs SET parts = $3::jsonb, pieces = ($3::jsonb -> part ->> 'pieces')::integer,"
                                " updated_at = now() WHERE id = $1 AND batch_id = $2",
                                split.job_id, lease.object_id, daemon::parts_to_json(split.parts).dump());
                            add_event(tx, split.job_id, node_, "split", split.note);
                          }
                          leave(nested.rejected, "failed", "failed");
                          leave(nested.waiting, "computed", "waiting");
                          leave(nested.held, "held", "held");
                          const bool any_left = !jobs_of(tx, lease.object_id).empty() && !nested.cut_file.empty();
                          const std::string reason =
                              any_left ? "" : nested.reason.empty() ? "nothing was placed" : nested.reason;
                          tx.exec_params(
                              "UPDATE batches SET state = $2, cut_file = $3, pieces = $4, utilisation = $5,"
                              " reason = nullif($6, ''), updated_at = now() WHERE id = $1",
                              lease.object_id, any_left ? "queued" : "dissolved", nested.cut_file, nested.pieces,
                              nested.utilisation, reason);
                          tx.exec_params(
                              "UPDATE hides SET state = $2, reason = nullif($3, ''), updated_at = now()"
                              " WHERE id = (SELECT hide_id FROM batches WHERE id = $1)",
                              lease.object_id, any_left ? "used" : "empty", reason);
                          for (long long id : jobs_of(tx, lease.object_id)) {
                            add_event(tx, id, node_, "nested", nested.cut_file);
                          }
                          release_lease(tx, lease);
                          return true;
                        })
      .status();
}

Result<std::optional<BatchClaim>> LedgerClient::claim_batch(double lease_s, const std::string& cutter) {
  using Claim = std::optional<BatchClaim>;
  return transact<Claim>("claiming a batch", [&](pqxx::work& tx) -> Result<Claim> {
    // Only the station a cutter is cabled to sends to it.
    const pqxx::result found = tx.exec_params(
        "SELECT b.id, b.cutter, b.material, b.cut_file FROM batches b JOIN cutters c ON c.name = b.cutter"
        " WHERE b.state = 'queued' AND c.station = $1 AND ($2 = '' OR b.cutter = $2) ORDER BY b.created_at, b.id"
        " LIMIT 1 FOR UPDATE OF b SKIP LOCKED",
        node_, cutter);
    if (found.empty()) return Claim();
    BatchClaim claim;
    claim.batch_id = found[0][0].as<long long>();
    claim.cutter = found[0][1].as<std::string>();
    claim.material = found[0][2].as<std::string>();
    claim.cut_file = found[0][3].as<std::string>();
    tx.exec_params("UPDATE batches SET state = 'claimed', updated_at = now() WHERE id = $1", claim.batch_id);
    claim.lease = {LeaseKind::Batch, claim.batch_id, take_lease(tx, node_, LeaseKind::Batch, claim.batch_id, lease_s)};
    fill_jobs(tx, claim);
    return Claim(std::move(claim));
  });
}

Status LedgerClient::mark_sending(const Lease& lease) {
  return transact<bool>("marking batch " + std::to_string(lease.object_id) + " sending",
                        [&](pqxx::work& tx) -> Result<bool> {
                          if (Status held = check_lease(tx, node_, lease); !held) return held;
                          if (Status claimed = batch_in(tx, lease.object_id, "claimed"); !claimed) return claimed;
                          tx.exec_params("UPDATE batches SET state = 'sending', updated_at = now() WHERE id = $1",
                                         lease.object_id);
                          for (long long id : jobs_of(tx, lease.object_id)) add_event(tx, id, node_, "sending");
                          return true;
                        })
      .status();
}

Status LedgerClient::mark_cut(const Lease& lease) {
  return transact<bool>("marking batch " + std::to_string(lease.object_id) + " cut",
                        [&](pqxx::work& tx) -> Result<bool> {
                          if (Status held = check_lease(tx, node_, lease); !held) return held;
                          if (Status sending = batch_in(tx, lease.object_id, "sending"); !sending) return sending;
                          tx.exec_params("UPDATE batches SET state = 'cut', updated_at = now() WHERE id = $1",
                                         lease.object_id);
                          // Each job's 'cut' names the batch (migrations/007_cut_events.sql): the overview
                          // counts a cut batch's jobs from these, as a job with a next part leaves it below.
                          tx.exec_params("INSERT INTO job_events (job_id, node, event, batch_id)"
                                         " SELECT id, $2, 'cut', $1 FROM jobs WHERE batch_id = $1 ORDER BY id",
                                         lease.object_id, node_);
                          // A job of several materials whose next part follows: computed again with it
                          // (migrations/006_parts.sql). SET reads the row as it was: part is the old one.
                          for (const pqxx::row& r : tx.exec_params(
                                   "UPDATE jobs SET state = 'computed', batch_id = NULL, part = part + 1,"
                                   " material = parts -> (part + 1) ->> 'material', cutter = parts -> (part + 1) ->> 'cutter',"
                                   " pieces = (parts -> (part + 1) ->> 'pieces')::integer, updated_at = now()"
                                   " WHERE batch_id = $1 AND part + 1 < jsonb_array_length(parts)"
                                   " RETURNING id, part + 1, jsonb_array_length(parts), pieces, material, cutter",
                                   lease.object_id)) {
                            add_event(tx, r[0].as<long long>(), node_, "computed",
                                      "next part " + r[1].as<std::string>() + " of " + r[2].as<std::string>() + ": " +
                                          daemon::pieces_of(r[3].as<int>(), r[4].as<std::string>()) + " for " +
                                          r[5].as<std::string>());
                          }
                          tx.exec_params("UPDATE jobs SET state = 'done', updated_at = now() WHERE batch_id = $1",
                                         lease.object_id);
                          release_lease(tx, lease);
                          return true;
                        })
      .status();
}

Status LedgerClient::mark_not_sent(const Lease& lease, const std::string& reason) {
  return transact<bool>("returning batch " + std::to_string(lease.object_id) + " to the queue",
                        [&](pqxx::work& tx) -> Result<bool> {
                          if (Status held = check_lease(tx, node_, lease); !held) return held;
                          if (Status sending = batch_in(tx, lease.object_id, "sending"); !sending) return sending;
                          tx.exec_params(
                              "UPDATE batches SET state = 'queued', reason = $2, updated_at = now() WHERE id = $1",
                              lease.object_id, reason);
                          for (long long id : jobs_of(tx, lease.object_id)) add_event(tx, id, node_, "not sent", reason);
                          release_lease(tx, lease);
                          return true;
                        })
      .status();
}

Status LedgerClient::hold_batch(const Lease& lease, const std::string& reason) {
  return transact<bool>("holding batch " + std::to_string(lease.object_id), [&](pqxx::work& tx) -> Result<bool> {
           if (Status held = check_lease(tx, node_, lease); !held) return held;
           tx.exec_params("UPDATE batches SET state = 'held', reason = $2, updated_at = now() WHERE id = $1",
                          lease.object_id, reason);
           tx.exec_params("UPDATE jobs SET state = 'held', reason = $2, updated_at = now() WHERE batch_id = $1",
                          lease.object_id, reason);
           for (long long id : jobs_of(tx, lease.object_id)) add_event(tx, id, node_, "held", reason);
           release_lease(tx, lease);
           return true;
         })
      .status();
}

Result<long long> LedgerClient::cancel_queued_batch(long long batch_id, const std::string& reason) {
  const std::string what = "batch " + std::to_string(batch_id);
  return transact<long long>("cancelling " + what, [&](pqxx::work& tx) -> Result<long long> {
    const pqxx::result row = tx.exec_params("SELECT state FROM batches WHERE id = $1 FOR UPDATE", batch_id);
    if (row.empty()) return Status::failure("no " + what + " in the ledger");
    const std::string state = row[0][0].as<std::string>();
    if (state != "queued") return Status::failure(what + " is " + state + ": only a batch waiting for its cutter can be cancelled");
    tx.exec_params("UPDATE batches SET state = 'held', reason = $2, updated_at = now() WHERE id = $1", batch_id, reason);
    tx.exec_params("UPDATE jobs SET state = 'held', reason = $2, updated_at = now() WHERE batch_id = $1", batch_id, reason);
    const std::vector<long long> jobs = jobs_of(tx, batch_id);
    for (long long id : jobs) add_event(tx, id, node_, "held", reason);
    return static_cast<long long>(jobs.size());
  });
}

}  // namespace lastcut::ledger
