#pragma once
// Inside the ledger client only: the transaction wrapper, the fencing check and the event row
// every state change writes. Included by the ledger_*.cpp files, never by users of the client.
#include <string>

#include <pqxx/pqxx>

#include "daemon/ledger/ledger_client.hpp"
#include "daemon/ledger/ledger_connection.hpp"

namespace lastcut::ledger {

template <typename T, typename Body>
Result<T> LedgerClient::transact(const std::string& doing, Body body) {
  return guarded<T>(doing, [&]() -> Result<T> {
    if (Status opened = open(); !opened) return opened;
    try {
      pqxx::work tx(*connection_);
      Result<T> result = body(tx);
      if (result) tx.commit();
      return result;
    } catch (const pqxx::broken_connection&) {
      connection_.reset();  // the next call connects again
      throw;
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

}  // namespace lastcut::ledger
