#pragma once
// Reading [ledger] (used by config_loader.cpp; kept apart so that daemon_config.hpp needs no TOML).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "daemon/config/ledger_config.hpp"

namespace lastcut::daemon {

// Reads [ledger] from `table` (relative shared_dir against `base`); each problem is appended to
// `errors` as "ledger.KEY (line N): why".
void read_ledger_table(const toml::table& table, const std::filesystem::path& base, std::optional<LedgerConfig>& out,
                       std::vector<std::string>& errors);

}  // namespace lastcut::daemon
