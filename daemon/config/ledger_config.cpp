// Validation of [ledger] (see ledger_config.hpp). Every key is checked; unknown keys are errors,
// as everywhere in the configuration (a typo must not silently fall back to the file spool).
#include "daemon/config/ledger_config_reader.hpp"

#include <algorithm>
#include <set>
#include <sstream>

namespace lastcut::daemon {
namespace {

std::string at(const std::string& key, const toml::node& node) {
  std::ostringstream out;
  out << "ledger." << key;
  if (node.source().begin.line > 0) out << " (line " << node.source().begin.line << ")";
  return out.str();
}

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

void read_ledger_table(const toml::table& table, const std::filesystem::path& base, std::optional<LedgerConfig>& out,
                       std::vector<std::string>& errors) {
  LedgerConfig config;
  const std::size_t errors_before = errors.size();
  const auto text = [&](const char* key, std::string& value) {
    const toml::node* node = table.get(key);
    if (!node) errors.push_back(std::string("ledger.") + key + ": missing (required)");
    else if (!node->is_string()) errors.push_back(at(key, *node) + ": must be a text in quotes");
    else value = *node->value<std::string>();
    return node;
  };
  const auto number = [&](const char* key, double& value, double min_value, double max_value) {
    const toml::node* node = table.get(key);
    if (!node) return;
    if (!node->is_number()) {
      errors.push_back(at(key, *node) + ": must be a number");
      return;
    }
    const double v = *node->value<double>();
    if (v < min_value || v > max_value) {
      std::ostringstream why;
      why << at(key, *node) << ": " << v << " is outside " << min_value << " .. " << max_value;
      errors.push_back(why.str());
      return;
    }
    value = v;
  };

  if (const toml::node* url = text("url", config.url);
      url && !config.url.empty() && config.url.rfind("postgresql://", 0) != 0 && config.url.rfind("postgres://", 0) != 0) {
    errors.push_back(at("url", *url) + ": must be a PostgreSQL URL, postgresql://user@host:5432/database");
  }
  if (const toml::node* node = text("node", config.node); node && node->is_string() && !valid_node_name(config.node)) {
    errors.push_back(at("node", *node) + ": \"" + config.node + "\" must be 1 to 63 letters, digits, '-', '_' or '.'");
  }
  std::string shared;
  if (text("shared_dir", shared) && !shared.empty()) {
    const std::filesystem::path path(shared);
    config.shared_dir = (path.is_absolute() ? path : base / path).lexically_normal();
  }
  if (const toml::node* roles = table.get("roles"); !roles) {
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
  number("lease_s", config.lease_s, 1, 3600);
  number("heartbeat_s", config.heartbeat_s, 0.1, 1800);
  if (config.heartbeat_s > config.lease_s / 2) {
    std::ostringstream why;
    why << "ledger.heartbeat_s: " << config.heartbeat_s << " must be at most half of lease_s (" << config.lease_s
        << "), or a busy node loses its claims";
    errors.push_back(why.str());
  }
  const std::set<std::string> known{"url", "node", "roles", "shared_dir", "lease_s", "heartbeat_s"};
  for (auto&& [key, value] : table) {
    if (!known.count(std::string(key.str()))) errors.push_back(at(std::string(key.str()), value) + ": unknown key");
  }
  if (errors.size() == errors_before) out = std::move(config);
}

}  // namespace lastcut::daemon
