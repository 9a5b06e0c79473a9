#pragma once
// Turning libpqxx's exceptions into Status/Result: nothing the database says escapes the ledger
// as an exception; each failure is one line naming what was being done and why
// ("ledger unreachable while claiming a job: connection to server at 127.0.0.1, port 5432 failed").
#include <functional>
#include <string>

#include <pqxx/except>

#include "engine/core/status.hpp"

namespace lastcut::ledger {

// libpq's multi-line messages folded to one line, trailing blanks removed.
std::string one_line(const std::string& text);

// The connection string with every secret replaced by "***", for logs, `lastcut status` and
// --check-config: in a URI the user's password and the query parameters password= and
// sslpassword=, in a keyword/value string ("host=h password=x") the values of those keywords.
std::string redact_url(const std::string& url);

// Whether a SQLSTATE says the connection is gone (classes 08 and 57P).
bool connection_lost(const std::string& sqlstate);

// Runs `body`; a pqxx or standard exception becomes a failure "<doing>: <reason>", and a lost
// connection says "ledger unreachable while <doing>: ..." so the caller can back off and retry.
template <typename T>
Result<T> guarded(const std::string& doing, const std::function<Result<T>()>& body) {
  try {
    return body();
  } catch (const pqxx::broken_connection& e) {
    return Status::failure("ledger unreachable while " + doing + ": " + one_line(e.what()));
  } catch (const pqxx::sql_error& e) {
    // The server going down under a running statement: SQLSTATE class 57P (shutdown, starting up)
    // or 08 (connection exception) is a lost connection too, not a refusal.
    if (connection_lost(e.sqlstate())) {
      return Status::failure("ledger unreachable while " + doing + ": " + one_line(e.what()));
    }
    return Status::failure("ledger error while " + doing + ": " + one_line(e.what()));
  } catch (const pqxx::in_doubt_error& e) {
    return Status::failure("ledger unreachable while " + doing + " (outcome unknown): " + one_line(e.what()));
  } catch (const std::exception& e) {
    return Status::failure("ledger error while " + doing + ": " + one_line(e.what()));
  }
}

// Whether a failure came from a lost connection (worth a retry with backoff).
bool unreachable(const Status& status);

}  // namespace lastcut::ledger
