// Applying the compiled-in migrations (see schema.hpp).
#include "daemon/ledger/schema.hpp"

#include <pqxx/pqxx>

#include "daemon/ledger/ledger_connection.hpp"

namespace lastcut::ledger {
namespace {

// pg_advisory_xact_lock key: "lastcut" in ASCII, so it does not collide with another program's lock.
constexpr long long kMigrationLockKey = 0x6c617374637574LL;

int current_version(pqxx::transaction_base& tx) {
  const pqxx::result exists = tx.exec("SELECT to_regclass('schema_version') IS NOT NULL");
  if (!exists[0][0].as<bool>()) return 0;
  return tx.exec("SELECT coalesce(max(version), 0) FROM schema_version")[0][0].as<int>();
}

std::string newer_schema(int found) {
  return "the ledger's schema is version " + std::to_string(found) + ", newer than this lastcutd knows (" +
         std::to_string(known_schema_version()) + "): update lastcutd on this node";
}

}  // namespace

int known_schema_version() { return migrations().empty() ? 0 : migrations().back().version; }

Result<int> read_schema_version(pqxx::connection_base& connection) {
  return guarded<int>("reading the ledger's schema version", [&]() -> Result<int> {
    pqxx::read_transaction tx(connection);
    return current_version(tx);
  });
}

Result<MigrationOutcome> apply_migrations(pqxx::connection_base& connection) {
  return guarded<MigrationOutcome>("migrating the ledger's schema", [&]() -> Result<MigrationOutcome> {
    pqxx::work tx(connection);
    // Nodes starting together wait here for each other; the lock ends with the transaction.
    tx.exec_params("SELECT pg_advisory_xact_lock($1)", kMigrationLockKey);
    tx.exec(
        "CREATE TABLE IF NOT EXISTS schema_version ("
        " version integer PRIMARY KEY, name text NOT NULL, applied_at timestamptz NOT NULL DEFAULT now())");
    MigrationOutcome outcome;
    outcome.version_before = current_version(tx);
    if (outcome.version_before > known_schema_version()) return Status::failure(newer_schema(outcome.version_before));
    for (const Migration& migration : migrations()) {
      if (migration.version <= outcome.version_before) continue;
      tx.exec(migration.sql);
      tx.exec_params("INSERT INTO schema_version (version, name) VALUES ($1, $2)", migration.version,
                     std::string(migration.name));
    }
    tx.commit();
    outcome.version_after = known_schema_version();
    return outcome;
  });
}

}  // namespace lastcut::ledger
