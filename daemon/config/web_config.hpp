#pragma once
// The [web] table: the operator's page that lastcutd serves (docs/operator-page.md). Absent, no
// socket is opened at all.
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lastcut::daemon {

struct WebConfig {
  std::string listen = "127.0.0.1:8631";  // as written: HOST:PORT (IPv4 address or name, or [IPv6])
  std::string host = "127.0.0.1";         // parsed from listen
  int port = 8631;                        // 0: any free port (written to the log; used by tests)
  std::filesystem::path assets_dir;       // the page's files; "" = where the package installs them
  // Who may act (requeue, load a hide): name -> secret, sent as "Authorization: Bearer SECRET".
  // The name is what the log shows as who acted. No tokens: the page is read-only.
  std::map<std::string, std::string> tokens;
  std::size_t max_body_bytes = 8u << 20;  // the largest request body (a hide upload)
  int requests_per_s = 50;                // per client address, bursts up to twice this
  int max_watchers = 24;                  // live pages connected at once (each holds a connection and a thread)
};

}  // namespace lastcut::daemon
