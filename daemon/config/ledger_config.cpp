// Validation of [ledger] (see ledger_config.hpp). Every key is checked; unknown keys are errors,
// as everywhere in the configuration (a typo must not silently fall back to the file spool).
#include "daemon/config/ledger_config_reader.hpp"

#include <algorithm>
#include <set>
#include <utility>
#include <sstream>

#include "daemon/config/table_reader.hpp"

namespace lastcut::daemon {
namespace {

bool valid_node_name(const std::string& name) {
  return !name.empty() && name.size() <= 63 && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
           c == '.';
  });
}

}  // namespace

bool LedgerConfig::has_role(const std::string& role) const {
  return std::find(roles.begin(), roles.end(), role) != roles.end();
}

bool LedgerConfig::owns_cutter(const std::string& cutter) const {
  return has_role("station") && (cutters.empty() || std::find(cutters.begin(), cutters.end(), cutter) != cutters.end());
}

void read_ledger_table(const toml::table& table, const std::filesystem::path& base, std::optional<LedgerConfig>& out,
                       std::vector<std::string>& errors) {
  LedgerConfig config;
  const std::size_t errors_before = errors.size();
  TableReader reader(table, "ledger", errors);
  // The key's node when it is present and a text (read into value), else nullptr.
  const auto text = [&](const char* key, std::string& value) -> const toml::node* {
    const std::size_t before = errors.size();
    reader.text(key, value, true);
    return errors.size() == before ? table.get(key) : nullptr;
  };
  const auto at = [&](const std::string& key, const toml::node& node) { return where(reader.key_path(key), node); };
  if (const toml::node* url = text("url", config.url);
      url && !config.url.empty() && config.url.rfind("postgresql://", 0) != 0 && config.url.rfind("postgres://", 0) != 0) {
    errors.push_back(at("url", *url) + ": must be a PostgreSQL URL, postgresql://user@host:5432/database");
  }
  if (const toml::node* node = text("node", config.node); node && !valid_node_name(config.node)) {
    errors.push_back(at("node", *node) + ": \"" + config.node + "\" must be 1 to 63 letters, digits, '-', '_' or '.'");
  }
  std::string shared;
  if (text("shared_dir", shared) && !shared.empty()) config.shared_dir = resolve(base, shared);
  if (const toml::node* roles = reader.node("roles"); !roles) {
    errors.push_back("ledger.roles: missing (required), e.g. [\"compute\", \"station\"]");
  } else if (!roles->is_array() || roles->as_array()->empty()) {
    errors.push_back(at("roles", *roles) + ": must be a list of one or both of \"compute\", \"station\"");
  } else {
    std::set<std::string> seen;
    for (const toml::node& role : *roles->as_array()) {
      const std::string name = role.is_string() ? *role.value<std::string>() : "";
      if (name != "compute" && name != "station") {
        errors.push_back(at("roles", role) + ": each entry must be \"compute\" or \"station\"");
      } else if (!seen.insert(name).second) {
        errors.push_back(at("roles", role) + ": \"" + name + "\" is listed twice");
      } else {
        config.roles.push_back(name);
      }
    }
  }
  if (const toml::node* cutters = reader.node("cutters")) {
    if (!cutters->is_array()) errors.push_back(at("cutters", *cutters) + ": must be a list of [cutters.*] names");
    else
      for (const toml::node& cutter : *cutters->as_array()) {
        if (!cutter.is_string()) errors.push_back(at("cutters", cutter) + ": each entry must be a cutter's name");
        else config.cutters.push_back(*cutter.value<std::string>());
      }
    if (!config.cutters.empty() && std::find(config.roles.begin(), config.roles.end(), "station") == config.roles.end()) {
      errors.push_back(at("cutters", *cutters) + ": only a node with the role \"station\" has cutters cabled to it");
    }
  }
  // One batching rule for the spool and the ledger since schema 4: the ledger's own keys name the new one.
  for (const auto& [old_key, new_key] : {std::pair{"batch_window_s", "[batch] window_s"},
                                         std::pair{"max_batch_jobs", "[batch] max_pieces (pieces, not jobs)"}}) {
    if (const toml::node* old = reader.node(old_key))
      errors.push_back(at(old_key, *old) + ": no longer read; use " + new_key +
                       ", the same batching rule as on one station (docs/multi-station.md, upgrading)");
  }
  reader.number("lease_s", config.lease_s, 1, 3600);
  reader.number("heartbeat_s", config.heartbeat_s, 0.1, 1800);
  if (config.heartbeat_s > config.lease_s / 2) {
    std::ostringstream why;
    why << "ledger.heartbeat_s: " << config.heartbeat_s << " must be at most half of lease_s (" << config.lease_s
        << "), or a busy node loses its claims";
    errors.push_back(why.str());
  }
  reader.reject_unknown();
  if (errors.size() == errors_before) out = std::move(config);
}

}  // namespace lastcut::daemon
