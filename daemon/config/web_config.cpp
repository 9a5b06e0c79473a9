// Validation of [web] (see web_config.hpp). A listen address that could reach past the machine is
// allowed (a shop may want the page on its network) but the log says so at start.
#include "daemon/config/web_config_reader.hpp"

#include <algorithm>

#include "daemon/config/table_reader.hpp"

namespace lastcut::daemon {
namespace {

bool valid_token_name(const std::string& name) {
  return !name.empty() && name.size() <= 40 && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
  });
}

// "HOST:PORT" or "[V6]:PORT" into host and port; "" when it parses, else why not.
std::string parse_listen(const std::string& listen, std::string& host, int& port) {
  const std::size_t colon = listen.rfind(':');
  if (colon == std::string::npos || colon == 0) return "must be HOST:PORT, e.g. \"127.0.0.1:8631\"";
  host = listen.substr(0, colon);
  if (host.front() == '[') {
    if (host.back() != ']' || host.size() < 3) return "must be HOST:PORT; an IPv6 host is written [::1]";
    host = host.substr(1, host.size() - 2);
  }
  const std::string digits = listen.substr(colon + 1);
  if (digits.empty() || digits.size() > 5 || !std::all_of(digits.begin(), digits.end(), ::isdigit))
    return "the port must be a number from 0 to 65535";
  port = std::stoi(digits);
  if (port > 65535) return "the port must be a number from 0 to 65535";
  return "";
}

}  // namespace

void read_web_table(const toml::table& table, const std::filesystem::path& base, std::optional<WebConfig>& out,
                    std::vector<std::string>& errors) {
  WebConfig config;
  const std::size_t errors_before = errors.size();
  TableReader reader(table, "web", errors);
  reader.text("listen", config.listen);
  if (std::string why = parse_listen(config.listen, config.host, config.port); !why.empty())
    errors.push_back("web.listen: \"" + config.listen + "\" " + why);
  std::string assets;
  reader.text("assets", assets);
  if (!assets.empty()) config.assets_dir = resolve(base, assets);
  if (const toml::table* tokens = reader.subtable("tokens", false)) {
    TableReader token_reader(*tokens, "web.tokens", errors);
    for (const auto& [key, node] : *tokens) {
      const std::string name(key.str());
      std::string secret;
      token_reader.text(name, secret);
      if (!valid_token_name(name)) {
        errors.push_back(where("web.tokens." + name, node) + ": a token's name is 1 to 40 letters, digits, '-' or '_'");
      } else if (secret.size() < 16) {
        errors.push_back(where("web.tokens." + name, node) + ": a token must be at least 16 characters (try `openssl rand -hex 16`)");
      } else {
        config.tokens[name] = secret;
      }
    }
  }
  double max_body_mib = static_cast<double>(config.max_body_bytes) / (1 << 20);
  reader.number("max_body_mib", max_body_mib, 0.01, 256);
  config.max_body_bytes = static_cast<std::size_t>(max_body_mib * (1 << 20));
  reader.integer("requests_per_s", config.requests_per_s, 1, 100000);
  reader.integer("max_watchers", config.max_watchers, 1, 200);
  reader.reject_unknown();
  if (errors.size() == errors_before) out = std::move(config);
}

}  // namespace lastcut::daemon
