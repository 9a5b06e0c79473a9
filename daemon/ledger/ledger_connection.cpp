// Error folding for the ledger (see ledger_connection.hpp).
#include "daemon/ledger/ledger_connection.hpp"

namespace lastcut::ledger {

std::string one_line(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n' || c == '\r' || c == '\t') {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += c;
    }
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

std::string redact_url(const std::string& url) {
  // postgresql://user:password@host/db: the password sits between the first ':' after the
  // scheme and the '@'.
  const std::size_t scheme = url.find("://");
  if (scheme == std::string::npos) return url;
  const std::size_t at = url.find('@', scheme + 3);
  if (at == std::string::npos) return url;
  const std::size_t colon = url.find(':', scheme + 3);
  if (colon == std::string::npos || colon > at) return url;
  return url.substr(0, colon + 1) + "***" + url.substr(at);
}

bool connection_lost(const std::string& sqlstate) {
  return sqlstate.rfind("08", 0) == 0 || sqlstate.rfind("57P", 0) == 0;
}

bool unreachable(const Status& status) { return status.error().rfind("ledger unreachable", 0) == 0; }

}  // namespace lastcut::ledger
