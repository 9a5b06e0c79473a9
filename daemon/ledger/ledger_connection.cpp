// Error folding for the ledger (see ledger_connection.hpp).
#include "daemon/ledger/ledger_connection.hpp"

#include <algorithm>
#include <string_view>

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

namespace {

// libpq's parameters that carry a secret: the server password and the client key's passphrase.
bool secret_key(std::string_view key) { return key == "password" || key == "sslpassword"; }

bool blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

// postgresql://user:password@host:port/db?key=value&...: the password of the user part (between
// the first ':' and the last '@' of the authority) and the value of a secret query parameter.
std::string redact_uri(const std::string& url, std::size_t authority) {
  std::string out = url;
  const std::size_t authority_end = std::min(out.find_first_of("/?#", authority), out.size());
  const std::size_t at = out.rfind('@', authority_end);
  if (at != std::string::npos && at >= authority) {
    const std::size_t colon = out.find(':', authority);
    if (colon < at) out.replace(colon + 1, at - colon - 1, "***");
  }
  const std::size_t query = out.find('?');
  if (query == std::string::npos) return out;
  for (std::size_t start = query + 1; start < out.size();) {
    std::size_t end = std::min(out.find('&', start), out.find('#', start));
    end = std::min(end, out.size());
    const std::size_t equals = out.find('=', start);
    if (equals < end && secret_key(std::string_view(out).substr(start, equals - start))) {
      out.replace(equals + 1, end - equals - 1, "***");
      end = equals + 4;
    }
    if (end >= out.size() || out[end] == '#') break;
    start = end + 1;
  }
  return out;
}

// host=h password=secret dbname=x (spaces around '=' allowed, a value may be 'single quoted' with
// \' and \\ escapes): the value of each secret keyword. Past anything it cannot read, the rest is
// replaced too, so a malformed string never shows a password.
std::string redact_keywords(const std::string& text) {
  std::string out;
  std::size_t i = 0;
  const std::size_t n = text.size();
  while (i < n) {
    const std::size_t token = i;
    while (i < n && blank(text[i])) ++i;
    const std::size_t key_start = i;
    while (i < n && !blank(text[i]) && text[i] != '=') ++i;
    const std::string_view key = std::string_view(text).substr(key_start, i - key_start);
    while (i < n && blank(text[i])) ++i;
    if (key.empty() || i >= n || text[i] != '=') {
      if (key.empty() && i >= n) return out + text.substr(token);  // trailing blanks
      return out + text.substr(token, key_start - token) + "***";
    }
    ++i;
    while (i < n && blank(text[i])) ++i;
    const std::size_t value_start = i;
    if (i < n && text[i] == '\'') {
      for (++i; i < n && text[i] != '\''; ++i) {
        if (text[i] == '\\') ++i;
      }
      if (i >= n) return out + text.substr(token, value_start - token) + "***";  // unterminated quote
      ++i;
    } else {
      while (i < n && !blank(text[i])) ++i;
    }
    out += text.substr(token, value_start - token);
    out += secret_key(key) ? "***" : text.substr(value_start, i - value_start);
  }
  return out;
}

}  // namespace

std::string redact_url(const std::string& url) {
  // libpq takes a URI (postgresql:// or postgres://) or a keyword/value string.
  for (const char* scheme : {"postgresql://", "postgres://"}) {
    const std::string_view prefix(scheme);
    if (url.compare(0, prefix.size(), prefix) == 0) return redact_uri(url, prefix.size());
  }
  return redact_keywords(url);
}

bool connection_lost(const std::string& sqlstate) {
  return sqlstate.rfind("08", 0) == 0 || sqlstate.rfind("57P", 0) == 0;
}

bool unreachable(const Status& status) { return status.error().rfind("ledger unreachable", 0) == 0; }

}  // namespace lastcut::ledger
