#pragma once
// `lastcutd --check-config` with [ledger]: connect, read the schema version (changing nothing),
// and say in one line whether this build can run against it.
#include <string>

#include "engine/core/status.hpp"

namespace lastcut::ledger {

// "ledger postgresql://u:***@h/db: reachable, schema version 1 (this lastcutd knows 1)", or the
// one-line reason it is not usable (unreachable, schema newer than this build).
Result<std::string> check_ledger(const std::string& url, const std::string& node);

}  // namespace lastcut::ledger
