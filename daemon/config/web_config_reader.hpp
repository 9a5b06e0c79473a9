#pragma once
// Reading [web] (used by config_loader.cpp; kept apart so that daemon_config.hpp needs no TOML).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "daemon/config/web_config.hpp"

namespace lastcut::daemon {

// Reads [web] from `table`; relative assets against `base`. Problems are appended to `errors` as
// "web.KEY (line N): why".
void read_web_table(const toml::table& table, const std::filesystem::path& base, std::optional<WebConfig>& out,
                    std::vector<std::string>& errors);

}  // namespace lastcut::daemon
