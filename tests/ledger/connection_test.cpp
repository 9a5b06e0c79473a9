// Losing the database: calls fail with one line saying the ledger is unreachable (never an
// exception), and the next call after the server is back reconnects; nothing committed is lost.
#include "daemon/ledger/ledger_connection.hpp"
#include "tests/ledger/ledger_fixture.hpp"

namespace lastcut::test {
namespace {

using ConnectionTest = LedgerTest;

TEST_F(ConnectionTest, ServerRestartIsSurvivedAndNothingIsLost) {
  auto a = client("node-a");
  ASSERT_TRUE(a);
  auto entered = a->enqueue(scan(1));
  ASSERT_TRUE(entered.ok());
  ASSERT_TRUE(server_.stop().empty());

  auto down = a->enqueue(scan(2));
  ASSERT_FALSE(down.ok());
  EXPECT_TRUE(ledger::unreachable(down.status())) << down.error();
  EXPECT_EQ(down.error().find('\n'), std::string::npos) << down.error();
  auto still_down = a->claim_job(30);
  ASSERT_FALSE(still_down.ok());
  EXPECT_TRUE(ledger::unreachable(still_down.status())) << still_down.error();

  ASSERT_TRUE(server_.start().empty());
  auto claim = a->claim_job(30);
  ASSERT_TRUE(claim.ok() && claim->has_value()) << claim.error();
  EXPECT_EQ((*claim)->job_id, entered->job_id);
  EXPECT_EQ(query("SELECT count(*) FROM jobs"), "1");  // the enqueue during the outage did not happen
}

TEST(LedgerConnection, UnreachableServerIsOneLineNotAnException) {
  auto refused = ledger::LedgerClient::connect("postgresql://lastcut:secret@127.0.0.1:1/lastcut", "node-a");
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().rfind("ledger unreachable while connecting to postgresql://lastcut:***@127.0.0.1:1/lastcut: ", 0),
            0u)
      << refused.error();
  EXPECT_EQ(refused.error().find('\n'), std::string::npos);
  EXPECT_EQ(refused.error().find("secret"), std::string::npos);
}

}  // namespace
}  // namespace lastcut::test
