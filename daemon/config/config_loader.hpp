#pragma once
// Reading and validating the daemon's TOML file. Everything is checked before the daemon uses
// it: unknown keys, wrong types and bad values are errors naming the key path and the line
// ("cutters.cutter-a.baud (line 31): must be a positive integer"), so a bad file or a bad
// reload (SIGHUP) never half-applies.
#include <filesystem>
#include <optional>
#include <string>

#include "daemon/config/daemon_config.hpp"

namespace lastcut::daemon {

struct ConfigLoadResult {
  std::optional<DaemonConfig> config;  // set when the file is valid
  std::string error;                   // one line per problem otherwise
};

// Relative paths in the file are taken relative to the file's folder.
ConfigLoadResult load_daemon_config(const std::filesystem::path& file);

}  // namespace lastcut::daemon
