#pragma once
// The ledger's schema: versioned migrations (daemon/ledger/migrations/NNN_name.sql, compiled in),
// applied at a node's start in one transaction under a PostgreSQL advisory lock, so that nodes
// starting together apply each migration once; a second start applies nothing. The applied
// versions are rows of schema_version. A node refuses a schema newer than the migrations it carries.
#include <string>
#include <vector>

#include "engine/core/status.hpp"

namespace pqxx {
class connection_base;
}

namespace lastcut::ledger {

struct Migration {
  int version;       // NNN of the file name, strictly increasing from 1
  const char* name;  // the file name's rest ("initial")
  const char* sql;
};

// Every migration this build carries, by version (generated from migrations/*.sql).
const std::vector<Migration>& migrations();
// The highest version this build knows.
int known_schema_version();

// The database's schema version: 0 for a database no node has prepared yet. Reads only.
Result<int> read_schema_version(pqxx::connection_base& connection);

struct MigrationOutcome {
  int version_before = 0;
  int version_after = 0;  // == known_schema_version()
};
// Brings the schema to known_schema_version(); refuses (one line, nothing changed) a database
// whose schema is newer than this build.
Result<MigrationOutcome> apply_migrations(pqxx::connection_base& connection);

}  // namespace lastcut::ledger
