// The shop at a glance for `lastcut status` on a ledger node: job counts per state, the nodes
// with the age of their heartbeat, the cutters with their station and queue, the held jobs.
#include <pqxx/pqxx>

#include "daemon/ledger/ledger_transaction.hpp"

namespace lastcut::ledger {

Result<LedgerOverview> LedgerClient::overview() {
  return transact<LedgerOverview>("reading the ledger's overview", [&](pqxx::work& tx) -> Result<LedgerOverview> {
    LedgerOverview out;
    for (const pqxx::row& r : tx.exec("SELECT state, count(*) FROM jobs GROUP BY state ORDER BY state")) {
      out.jobs_per_state.emplace_back(r[0].as<std::string>(), r[1].as<long long>());
    }
    for (const pqxx::row& r :
         tx.exec("SELECT material, count(*), coalesce(sum(pieces), 0) FROM jobs WHERE state = 'computed' GROUP BY material ORDER BY material")) {
      out.computed_per_material.push_back({r[0].as<std::string>(), r[1].as<long long>(), r[2].as<long long>()});
    }
    for (const pqxx::row& r : tx.exec(
             "SELECT name, array_to_string(roles, ','), extract(epoch FROM now() - heartbeat_at)::float8"
             " FROM nodes ORDER BY name")) {
      out.nodes.push_back({r[0].as<std::string>(), r[1].as<std::string>(), r[2].as<double>()});
    }
    for (const pqxx::row& r : tx.exec(
             "SELECT c.name, c.station, (SELECT count(*) FROM batches b WHERE b.cutter = c.name AND b.state = 'queued')"
             " FROM cutters c ORDER BY c.name")) {
      out.cutters.push_back({r[0].as<std::string>(), r[1].as<std::string>(), r[2].as<long long>()});
    }
    for (const pqxx::row& r : tx.exec(
             "SELECT b.id, b.cutter, (SELECT count(*) FROM jobs j WHERE j.batch_id = b.id), coalesce(b.pieces, 0)"
             " FROM batches b WHERE b.state = 'queued' ORDER BY b.created_at, b.id LIMIT 100")) {
      out.queued_batches.push_back({r[0].as<long long>(), r[1].as<std::string>(), r[2].as<long long>(), r[3].as<int>()});
    }
    for (const pqxx::row& r : tx.exec(
             "SELECT b.id, to_char(b.updated_at AT TIME ZONE 'UTC', 'YYYY-MM-DD\"T\"HH24:MI:SS.MS\"Z\"'), b.material,"
             // A job cut in parts has left the batch of an earlier part: its 'cut' event names it.
             " (SELECT count(DISTINCT e.job_id) FROM job_events e WHERE e.batch_id = b.id AND e.event = 'cut'),"
             " coalesce(b.pieces, 0), coalesce(b.utilisation, 0)"
             " FROM batches b WHERE b.state = 'cut' AND b.updated_at > now() - interval '24 hours'"
             " ORDER BY b.updated_at, b.id LIMIT 5000")) {
      out.cut_last_24h.push_back({r[0].as<long long>(), r[1].as<std::string>(), r[2].as<std::string>(),
                                  r[3].as<long long>(), r[4].as<int>(), r[5].as<double>()});
    }
    return out;
  });
}

}  // namespace lastcut::ledger
