// Migrations: applied once, idempotent, serialised between nodes starting together, and a
// schema newer than the build is refused with one line.
#include <thread>

#include "daemon/ledger/schema.hpp"
#include "tests/ledger/ledger_fixture.hpp"

namespace lastcut::test {
namespace {

using SchemaTest = LedgerTest;

TEST_F(SchemaTest, MigrationsApplyOnceAndCreateEveryTable) {
  ASSERT_GE(ledger::known_schema_version(), 1);
  auto connected = ledger::LedgerClient::connect(url_, "node-a");
  ASSERT_TRUE(connected.ok()) << connected.error();
  auto& client = **connected;
  auto before = client.schema_version();
  ASSERT_TRUE(before.ok()) << before.error();
  EXPECT_EQ(*before, 0);

  auto first = client.migrate();
  ASSERT_TRUE(first.ok()) << first.error();
  EXPECT_EQ(first->version_before, 0);
  EXPECT_EQ(first->version_after, ledger::known_schema_version());
  auto second = client.migrate();
  ASSERT_TRUE(second.ok()) << second.error();
  EXPECT_EQ(second->version_before, ledger::known_schema_version());
  EXPECT_EQ(query("SELECT count(*) FROM schema_version"), std::to_string(ledger::migrations().size()));
  for (const char* table : {"nodes", "cutters", "hides", "batches", "jobs", "leases", "job_events"}) {
    EXPECT_EQ(query(std::string("SELECT to_regclass('") + table + "') IS NOT NULL"), "t") << table;
  }
}

TEST_F(SchemaTest, NodesStartingTogetherApplyEachMigrationOnce) {
  constexpr int kNodes = 6;
  std::vector<std::thread> nodes;
  std::vector<std::string> errors(kNodes);
  for (int i = 0; i < kNodes; ++i) {
    nodes.emplace_back([&, i] {
      auto connected = ledger::LedgerClient::connect(url_, "node-" + std::to_string(i));
      if (!connected) {
        errors[i] = connected.error();
        return;
      }
      if (auto migrated = (*connected)->migrate(); !migrated) errors[i] = migrated.error();
    });
  }
  for (auto& node : nodes) node.join();
  for (const auto& error : errors) EXPECT_EQ(error, "");
  EXPECT_EQ(query("SELECT count(*) FROM schema_version"), std::to_string(ledger::migrations().size()));
}

TEST_F(SchemaTest, NewerSchemaIsRefusedWithOneLine) {
  auto node = client("node-a");
  ASSERT_TRUE(node);
  const int newer = ledger::known_schema_version() + 1;
  {
    pqxx::connection connection(url_);
    pqxx::work tx(connection);
    tx.exec_params("INSERT INTO schema_version (version, name) VALUES ($1, 'from_the_future')", newer);
    tx.commit();
  }
  auto version = node->schema_version();
  ASSERT_TRUE(version.ok()) << version.error();
  EXPECT_EQ(*version, newer);
  auto refused = node->migrate();
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error(), "the ledger's schema is version " + std::to_string(newer) +
                                 ", newer than this lastcutd knows (" + std::to_string(newer - 1) +
                                 "): update lastcutd on this node");
}

}  // namespace
}  // namespace lastcut::test
