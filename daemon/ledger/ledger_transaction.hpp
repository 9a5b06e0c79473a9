#pragma once
// Inside the ledger client only: the transaction wrapper, the fencing check and the event row
// every state change writes. Included by the ledger_*.cpp files, never by users of the client.
#include <string>

#include <pqxx/pqxx>

#include "daemon/ledger/ledger_client.hpp"
#include "daemon/ledger/ledger_connection.hpp"

namespace lastcut::ledger {

// A connection found dead (the server restarted since the last call) is opened again and the
// transaction run once more: nothing of it was committed (a commit whose outcome is unknown is
// pqxx::in_doubt_error, never retried).
template <typename T, typename Body>
Result<T> LedgerClient::transact(const std::string& doing, Body body) {
  return guarded<T>(doing, [&]() -> Result<T> {
    for (int attempt = 1;; ++attempt) {
      if (Status opened = open(); !opened) return opened;
      try {
        pqxx::work tx(*connection_);
        Result<T> result = body(tx);
        if (result) tx.commit();
        return result;
      } catch (const pqxx::broken_connection&) {
        connection_.reset();
        if (attempt == 2) throw;
      } catch (const pqxx::sql_error& e) {
        if (!connection_lost(e.sqlstate())) throw;
        connection_.reset();
        if (attempt == 2) throw;
      }
    }
  });
}

// Locks the lease row and checks that this node still holds it with the epoch of its claim;
// otherwise "lease lost: ..." and the caller's transaction changes nothing.
Status check_lease(pqxx::work& tx, const std::string& node, const Lease& lease);

// Takes (or takes again) the lease on a row: holder = node, epoch + 1; returns the new epoch.
long long take_lease(pqxx::work& tx, const std::string& node, LeaseKind kind, long long object_id, double lease_s);

// Ends a lease after the last state change of a claim (the epoch stays for the next claim).
void release_lease(pqxx::work& tx, const Lease& lease);

void add_event(pqxx::work& tx, long long job_id, const std::string& node, const std::string& event,
               const std::string& detail = "");

// "{1,2,3}": a list of ids as one bigint[] parameter.
std::string id_array(const std::vector<long long>& ids);
// {"a","b"}: a list of names as one text[] parameter.
std::string text_array(const std::vector<std::string>& items);

// The batch's jobs (scans, names, tickets), ascending, and its hide, into `claim` (batch_id set).
void fill_jobs(pqxx::work& tx, BatchClaim& claim);

}  // namespace lastcut::ledger
