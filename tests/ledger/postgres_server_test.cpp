// The test harness itself: a real server starts, keeps committed data over a restart on the same
// port, and leaves nothing behind.
#include <gtest/gtest.h>

#include <filesystem>

#include <pqxx/pqxx>

#include "tests/support/postgres_server.hpp"

namespace lastcut::test {
namespace {

TEST(PostgresServer, StartsAnswersRestartsAndCleansUp) {
  std::filesystem::path folder;
  {
    PostgresServer server;
    const std::string failure = server.start();
    ASSERT_TRUE(failure.empty()) << failure;
    folder = server.folder();
    ASSERT_TRUE(std::filesystem::is_directory(folder / "data"));
    std::string error;
    const std::string url = server.create_database("harness", error);
    ASSERT_FALSE(url.empty()) << error;
    {
      pqxx::connection connection(url);
      pqxx::work tx(connection);
      EXPECT_EQ(tx.exec("SHOW server_version_num")[0][0].as<int>() / 10000, 15);
      tx.exec("CREATE TABLE kept (n integer)");
      tx.exec("INSERT INTO kept VALUES (42)");
      tx.commit();
    }
    const int port = server.port();
    ASSERT_TRUE(server.stop().empty());
    EXPECT_FALSE(server.running());
    EXPECT_THROW(pqxx::connection{url}, pqxx::broken_connection);
    const std::string restarted = server.start();
    ASSERT_TRUE(restarted.empty()) << restarted;
    EXPECT_EQ(server.port(), port);
    pqxx::connection connection(url);
    pqxx::read_transaction tx(connection);
    EXPECT_EQ(tx.exec("SELECT n FROM kept")[0][0].as<int>(), 42);
  }
  EXPECT_FALSE(std::filesystem::exists(folder)) << folder;
}

}  // namespace
}  // namespace lastcut::test
