// The hide half of the ledger queue (migration 003_hides.sql): a hide entered as lying on a
// cutter's table, nested by a compute node with the computed jobs of its material (the jobs that
// do not fit go back to wait for the next hide, see mark_nested), then cut like any batch.
#include <optional>

#include <pqxx/pqxx>

#include "daemon/ledger/ledger_transaction.hpp"

namespace lastcut::ledger {

Result<long long> LedgerClient::enter_hide(const HideEntry& hide) {
  return transact<long long>("entering hide " + hide.name, [&](pqxx::work& tx) -> Result<long long> {
    const pqxx::result known = tx.exec_params(
        "SELECT id, state, cutter FROM hides WHERE name = $1 FOR UPDATE", hide.name);
    if (!known.empty() && known[0][1].as<std::string>() != "empty" && known[0][1].as<std::string>() != "available") {
      return Status::failure("hide " + hide.name + " is already in the ledger (" + known[0][1].as<std::string>() +
                             ", on cutter " + known[0][2].as<std::string>() +
                             "): a hide is cut once; give a new hide its own ID");
    }
    const pqxx::result row = tx.exec_params(
        "INSERT INTO hides (name, material, state, cutter, hide_file, area_m2, entered_by)"
        " VALUES ($1, $2, 'loaded', $3, $4, $5, $6)"
        " ON CONFLICT (name) DO UPDATE SET material = EXCLUDED.material, state = 'loaded', cutter = EXCLUDED.cutter,"
        " hide_file = EXCLUDED.hide_file, area_m2 = EXCLUDED.area_m2, entered_by = EXCLUDED.entered_by,"
        " reason = NULL, updated_at = now() RETURNING id",
        hide.name, hide.material, hide.cutter, hide.hide_file, hide.area_m2, node_);
    return row[0][0].as<long long>();
  });
}

Result<std::optional<BatchClaim>> LedgerClient::make_hide_batch(const HideDue& due, int max_jobs, double lease_s) {
  using Claim = std::optional<BatchClaim>;
  return transact<Claim>("nesting a hide", [&](pqxx::work& tx) -> Result<Claim> {
    // The oldest loaded hide that the rule finds due, given the jobs of its material.
    const pqxx::result loaded = tx.exec(
        "SELECT h.id, h.cutter, h.material, extract(epoch FROM now() - h.updated_at),"
        " (SELECT count(*) FROM jobs j WHERE j.state = 'computed' AND j.material = h.material),"
        " EXISTS (SELECT 1 FROM jobs j WHERE j.state IN ('ready', 'computing') AND j.material = h.material)"
        " FROM hides h WHERE h.state = 'loaded' ORDER BY h.updated_at, h.id FOR UPDATE OF h SKIP LOCKED");
    std::optional<pqxx::row> hide;
    for (const pqxx::row& r : loaded) {
      if (due(r[4].as<long long>(), r[5].as<bool>(), r[3].as<double>())) {
        hide = r;
        break;
      }
    }
    if (!hide) return Claim();
    BatchClaim claim;
    const long long hide_id = (*hide)[0].as<long long>();
    claim.cutter = (*hide)[1].as<std::string>();
    claim.material = (*hide)[2].as<std::string>();
    std::vector<long long> ids;
    for (const pqxx::row& r : tx.exec_params(
             "SELECT id FROM jobs WHERE state = 'computed' AND material = $1 ORDER BY created_at, id LIMIT $2"
             " FOR UPDATE SKIP LOCKED",
             claim.material, max_jobs)) {
      ids.push_back(r[0].as<long long>());
    }
    if (ids.empty()) return Claim();  // another node is grouping them right now
    claim.batch_id = tx.exec_params1(
                           "INSERT INTO batches (cutter, material, state, hide_id, created_by)"
                           " VALUES ($1, $2, 'nesting', $3, $4) RETURNING id",
                           claim.cutter, claim.material, hide_id, node_)[0]
                         .as<long long>();
    tx.exec_params("UPDATE hides SET state = 'nesting', updated_at = now() WHERE id = $1", hide_id);
    tx.exec_params("UPDATE jobs SET state = 'batched', batch_id = $1, updated_at = now() WHERE id = ANY($2::bigint[])",
                   claim.batch_id, id_array(ids));
    fill_jobs(tx, claim);
    for (long long id : claim.job_ids) {
      add_event(tx, id, node_, "batched",
                "hide " + claim.hide_name + " (batch " + std::to_string(claim.batch_id) + ") on " + claim.cutter);
    }
    claim.lease = {LeaseKind::Batch, claim.batch_id, take_lease(tx, node_, LeaseKind::Batch, claim.batch_id, lease_s)};
    return Claim(std::move(claim));
  });
}

Result<std::vector<HideRow>> LedgerClient::recent_hides(int limit) {
  using Rows = std::vector<HideRow>;
  return transact<Rows>("reading the hides", [&](pqxx::work& tx) -> Result<Rows> {
    Rows out;
    for (const pqxx::row& r : tx.exec_params(
             "SELECT h.id, h.name, h.material, h.cutter, h.state, coalesce(h.reason, ''), h.entered_by, h.area_m2,"
             " coalesce(b.id, 0), coalesce(b.pieces, 0), coalesce(b.utilisation, 0)"
             " FROM hides h LEFT JOIN LATERAL (SELECT id, pieces, utilisation FROM batches"
             "   WHERE hide_id = h.id ORDER BY id DESC LIMIT 1) b ON true"
             " ORDER BY h.updated_at DESC, h.id DESC LIMIT $1",
             limit)) {
      HideRow row;
      row.hide_id = r[0].as<long long>();
      row.name = r[1].as<std::string>();
      row.material = r[2].as<std::string>();
      row.cutter = r[3].as<std::string>();
      row.state = r[4].as<std::string>();
      row.reason = r[5].as<std::string>();
      row.entered_by = r[6].as<std::string>();
      row.area_m2 = r[7].as<double>();
      row.batch_id = r[8].as<long long>();
      row.pieces = r[9].as<int>();
      row.utilisation = r[10].as<double>();
      out.push_back(std::move(row));
    }
    return out;
  });
}

}  // namespace lastcut::ledger
