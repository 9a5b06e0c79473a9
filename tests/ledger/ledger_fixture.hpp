#pragma once
// A fresh PostgreSQL server and database per test, and ledger clients on it (migrated).
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>

#include <pqxx/pqxx>

#include "daemon/ledger/ledger_client.hpp"
#include "tests/support/postgres_server.hpp"

namespace lastcut::test {

class LedgerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string failure = server_.start();
    ASSERT_TRUE(failure.empty()) << failure;
    std::string error;
    url_ = server_.create_database("lastcut", error);
    ASSERT_FALSE(url_.empty()) << error;
  }

  // A client of node `name` on the test's database, the schema migrated.
  std::unique_ptr<ledger::LedgerClient> client(const std::string& name) {
    auto connected = ledger::LedgerClient::connect(url_, name);
    EXPECT_TRUE(connected.ok()) << connected.error();
    if (!connected) return nullptr;
    auto migrated = (*connected)->migrate();
    EXPECT_TRUE(migrated.ok()) << migrated.error();
    return std::move(*connected);
  }

  // One value of a query, as text, read over a connection of its own (an independent look).
  std::string query(const std::string& sql) {
    pqxx::connection connection(url_);
    pqxx::read_transaction tx(connection);
    const pqxx::result r = tx.exec(sql);
    return r.empty() || r[0][0].is_null() ? "" : r[0][0].as<std::string>();
  }

  PostgresServer server_;
  std::string url_;
};

// A scan entry whose hash is derived from `n` (64 hex digits, distinct per n).
inline ledger::ScanEntry scan(int n, const std::string& cutter = "cutter-1", const std::string& material = "calf") {
  char hex[65];
  std::snprintf(hex, sizeof(hex), "%064x", n);
  return {hex, "scan-" + std::to_string(n) + ".stl", "", material, cutter};
}

// What a compute node does to a batch (nothing is really nested here): groups the oldest computed
// jobs (no window) and hands the batch to its station with a cut file named after it. nullopt when
// nothing is computed; the failure of a ledger call fails the test.
inline std::optional<long long> nest_batch(ledger::LedgerClient& compute, int max_jobs) {
  auto made = compute.make_batch(max_jobs, 0, 30);
  EXPECT_TRUE(made.ok()) << made.error();
  if (!made || !made->has_value()) return std::nullopt;
  const long long id = (*made)->batch_id;
  const Status nested =
      compute.mark_nested((*made)->lease, {"batches/" + std::to_string(id) + "/cut.nc", 1, {}});
  EXPECT_TRUE(nested.ok()) << nested.error();
  return id;
}

}  // namespace lastcut::test
