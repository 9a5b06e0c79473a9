// The ledger line of `lastcutd --check-config` (see ledger_check.hpp).
#include "daemon/ledger/ledger_check.hpp"

#include "daemon/ledger/ledger_client.hpp"
#include "daemon/ledger/ledger_connection.hpp"

namespace lastcut::ledger {

Result<std::string> check_ledger(const std::string& url, const std::string& node) {
  auto client = LedgerClient::connect(url, node);
  if (!client) return client.status();
  auto version = (*client)->schema_version();
  if (!version) return version.status();
  const std::string known = std::to_string(known_schema_version());
  const std::string head = "ledger " + redact_url(url) + ": ";
  if (*version > known_schema_version()) {
    return Status::failure(head + "schema version " + std::to_string(*version) + " is newer than this lastcutd knows (" +
                           known + "): update lastcutd on this node");
  }
  if (*version == 0) return head + "reachable, no schema yet (version " + known + " is applied at the first start)";
  return head + "reachable, schema version " + std::to_string(*version) + " (this lastcutd knows " + known +
         (*version < known_schema_version() ? ", applies the rest at start)" : ")");
}

}  // namespace lastcut::ledger
