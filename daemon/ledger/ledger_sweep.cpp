// Leases nobody renews any more: those that expired (sweep_expired, any node) and those an
// earlier run of this node left behind (register_node at start). Jobs in computation go back to
// the queue; batches being nested are dissolved (their jobs regrouped), claimed batches not yet
// sending are queued again; a batch that was sending is held with its
// jobs, never re-sent (the cutter may have cut part of it).
#include <pqxx/pqxx>

#include "daemon/ledger/ledger_transaction.hpp"

namespace lastcut::ledger {
namespace {

// A station that has not renewed its heartbeat this long may lose its cutters to another node.
constexpr double kStationSilentS = 60;

// Releases every lease matching `condition` (SQL over leases; $1 is `parameter`) that no other
// transaction is acting on right now, and moves the rows they covered.
SweepOutcome release_matching(pqxx::work& tx, const std::string& node, const std::string& condition,
                              const std::string& parameter, int max_attempts) {
  const pqxx::result released = tx.exec_params(
      "WITH old AS (SELECT kind, object_id, holder FROM leases WHERE holder IS NOT NULL AND (" + condition +
          ") FOR UPDATE SKIP LOCKED)"
          " UPDATE leases l SET holder = NULL, expires_at = NULL FROM old"
          " WHERE l.kind = old.kind AND l.object_id = old.object_id RETURNING old.kind, old.object_id, old.holder",
      parameter);
  SweepOutcome out;
  for (const pqxx::row& r : released) {
    const std::string kind = r[0].as<std::string>();
    const long long id = r[1].as<long long>();
    const std::string holder = r[2].as<std::string>();
    if (kind == "job") {
      const pqxx::result job = tx.exec_params(
          "UPDATE jobs SET state = CASE WHEN attempts >= $2 THEN 'failed' ELSE 'ready' END,"
          " reason = CASE WHEN attempts >= $2 THEN $3 ELSE reason END, updated_at = now()"
          " WHERE id = $1 AND state = 'computing' RETURNING state",
          id, max_attempts,
          "the computation was interrupted " + std::to_string(max_attempts) + " times (last on " + holder + ")");
      if (job.empty()) continue;
      const bool failed = job[0][0].as<std::string>() == "failed";
      (failed ? out.jobs_failed : out.jobs_requeued).push_back(id);
      add_event(tx, id, node, failed ? "failed" : "requeued", "lease of " + holder + " ended without a result");
      continue;
    }
    const pqxx::result batch = tx.exec_params("SELECT state FROM batches WHERE id = $1 FOR UPDATE", id);
    if (batch.empty()) continue;
    const std::string state = batch[0][0].as<std::string>();
    if (state == "nesting") {
      // Nothing was written for the station yet: the jobs go back to be grouped (by any node) anew.
      for (const pqxx::row& j : tx.exec_params(
               "UPDATE jobs SET state = 'computed', batch_id = NULL, updated_at = now() WHERE batch_id = $1 RETURNING id",
               id)) {
        add_event(tx, j[0].as<long long>(), node, "regrouped", "nesting on " + holder + " ended without a result");
      }
      tx.exec_params("UPDATE batches SET state = 'dissolved', updated_at = now() WHERE id = $1", id);
      // A hide it was nesting still lies on the cutter's table: it is nested again.
      tx.exec_params(
          "UPDATE hides SET state = 'loaded', updated_at = now() WHERE id = (SELECT hide_id FROM batches WHERE id = $1)"
          " AND state = 'nesting'",
          id);
      out.batches_dissolved.push_back(id);
    } else if (state == "claimed") {
      tx.exec_params("UPDATE batches SET state = 'queued', updated_at = now() WHERE id = $1", id);
      out.batches_requeued.push_back(id);
    } else if (state == "sending") {
      const std::string reason = "station " + holder + " stopped answering while sending batch " + std::to_string(id) +
                                 ": check the cutter's table, then lastcut requeue";
      tx.exec_params("UPDATE batches SET state = 'held', reason = $2, updated_at = now() WHERE id = $1", id, reason);
      for (const pqxx::row& j : tx.exec_params(
               "UPDATE jobs SET state = 'held', reason = $2, updated_at = now() WHERE batch_id = $1"
               " RETURNING id, scan_name, ticket, cutter",
               id, reason)) {
        add_event(tx, j[0].as<long long>(), node, "held", reason);
        out.jobs_held.push_back(
            {j[0].as<long long>(), id, j[1].as<std::string>(), j[2].as<std::string>(), j[3].as<std::string>(), reason});
      }
      out.batches_held.push_back(id);
    }
  }
  return out;
}

}  // namespace

Result<SweepOutcome> LedgerClient::sweep_expired(int max_attempts, double grace_s) {
  return transact<SweepOutcome>("returning expired leases", [&](pqxx::work& tx) -> Result<SweepOutcome> {
    return release_matching(tx, node_, "expires_at < now() - make_interval(secs => $1::float8)",
                            std::to_string(grace_s), max_attempts);
  });
}

Result<std::vector<long long>> LedgerClient::batches_without_use(const std::vector<long long>& batch_ids) {
  using Ids = std::vector<long long>;
  return transact<Ids>("looking up batch folders", [&](pqxx::work& tx) -> Result<Ids> {
    Ids unused;
    for (const pqxx::row& r : tx.exec_params(
             "SELECT u.id FROM unnest($1::bigint[]) AS u(id)"
             " WHERE NOT EXISTS (SELECT 1 FROM batches b WHERE b.id = u.id AND b.state <> 'dissolved') ORDER BY u.id",
             id_array(batch_ids)))
      unused.push_back(r[0].as<long long>());
    return unused;
  });
}

Result<SweepOutcome> LedgerClient::register_node(const std::vector<std::string>& roles,
                                                 const std::vector<std::string>& cutters,
                                                 int max_attempts) {
  return transact<SweepOutcome>("registering node " + node_, [&](pqxx::work& tx) -> Result<SweepOutcome> {
    tx.exec_params(
        "INSERT INTO nodes (name, roles) VALUES ($1, $2::text[]) ON CONFLICT (name) DO UPDATE"
        " SET roles = EXCLUDED.roles, started_at = now(), heartbeat_at = now()",
        node_, text_array(roles));
    for (const std::string& cutter : cutters) {
      // A cutter is re-cabled to this node only when its former station has been silent for a
      // while; two live stations naming one cutter is a configuration mistake.
      const pqxx::result owner = tx.exec_params(
          "SELECT c.station FROM cutters c JOIN nodes n ON n.name = c.station WHERE c.name = $1 AND c.station <> $2"
          " AND n.heartbeat_at > now() - make_interval(secs => $3) FOR UPDATE OF c",
          cutter, node_, kStationSilentS);
      if (!owner.empty()) {
        return Status::failure("cutter " + cutter + " is cabled to station " + owner[0][0].as<std::string>() +
                               ", which is running: remove [cutters." + cutter + "] from one of the two configurations");
      }
      tx.exec_params(
          "INSERT INTO cutters (name, station) VALUES ($1, $2) ON CONFLICT (name) DO UPDATE"
          " SET station = EXCLUDED.station, updated_at = now()",
          cutter, node_);
    }
    // A previous run of this node is gone: nothing it held is being worked on any more.
    return release_matching(tx, node_, "holder = $1", node_, max_attempts);
  });
}

}  // namespace lastcut::ledger
