// [ledger] in the daemon configuration: absent means the file spool; present, every key is
// checked and each mistake is one line with the key path and the line.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "daemon/config/config_loader.hpp"
#include "tests/support/minimal_daemon_config.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut::daemon {
namespace {

const std::string kBase = "\n" + lastcut::testing::kMinimalDaemonConfig;

class LedgerConfigTest : public ::testing::Test {
 protected:

  ConfigLoadResult load(const std::string& ledger_table) {
    std::ofstream(folder_ / "lastcut.toml") << kBase << ledger_table;
    return load_daemon_config(folder_ / "lastcut.toml");
  }
  // The line of the first line of `ledger_table` in the file (kBase ends with a newline).
  int line_of(int index_in_table) const {
    return static_cast<int>(std::count(kBase.begin(), kBase.end(), '\n')) + 1 + index_in_table;
  }

  const test::TempDir folder_{"ledger-config"};
};

TEST_F(LedgerConfigTest, AbsentTableMeansTheFileSpool) {
  const auto result = load("");
  ASSERT_TRUE(result.config) << result.error;
  EXPECT_FALSE(result.config->ledger.has_value());
}

TEST_F(LedgerConfigTest, CompleteTableIsRead) {
  const auto result = load(R"([ledger]
url = "postgresql://lastcut@db.shop:5432/lastcut"
node = "station-1"
roles = ["compute", "station"]
shared_dir = "shared"
lease_s = 20
heartbeat_s = 4
)");
  ASSERT_TRUE(result.config) << result.error;
  ASSERT_TRUE(result.config->ledger.has_value());
  const LedgerConfig& ledger = *result.config->ledger;
  EXPECT_EQ(ledger.url, "postgresql://lastcut@db.shop:5432/lastcut");
  EXPECT_EQ(ledger.node, "station-1");
  EXPECT_EQ(ledger.roles, (std::vector<std::string>{"compute", "station"}));
  EXPECT_TRUE(ledger.has_role("station"));
  EXPECT_EQ(ledger.shared_dir, (std::filesystem::absolute(folder_) / "shared").lexically_normal());
  EXPECT_DOUBLE_EQ(ledger.lease_s, 20);
  EXPECT_DOUBLE_EQ(ledger.heartbeat_s, 4);
}

TEST_F(LedgerConfigTest, DefaultsForLeaseAndHeartbeat) {
  const auto result = load("[ledger]\nurl = \"postgres://h/db\"\nnode = \"n\"\nroles = [\"compute\"]\nshared_dir = \"/srv/lastcut\"\n");
  ASSERT_TRUE(result.config) << result.error;
  EXPECT_DOUBLE_EQ(result.config->ledger->lease_s, 30);
  EXPECT_DOUBLE_EQ(result.config->ledger->heartbeat_s, 5);
  EXPECT_FALSE(result.config->ledger->has_role("station"));
}

TEST_F(LedgerConfigTest, EveryMistakeIsOneLineWithKeyAndLine) {
  const auto result = load(R"([ledger]
url = "mysql://h/db"
node = "station 1"
roles = ["compute", "cutter", "compute"]
lease_s = 10
heartbeat_s = 6
colour = "blue"
)");
  ASSERT_FALSE(result.config);
  const std::string file = (folder_ / "lastcut.toml").string() + ": ";
  const std::vector<std::string> expected = {
      "ledger.url (line " + std::to_string(line_of(1)) + "): must be a PostgreSQL URL, postgresql://user@host:5432/database",
      "ledger.node (line " + std::to_string(line_of(2)) + "): \"station 1\" must be 1 to 63 letters, digits, '-', '_' or '.'",
      "ledger.shared_dir: missing (required)",
      "ledger.roles (line " + std::to_string(line_of(3)) + "): each entry must be \"compute\" or \"station\"",
      "ledger.roles (line " + std::to_string(line_of(3)) + "): \"compute\" is listed twice",
      "ledger.heartbeat_s: 6 must be at most half of lease_s (10), or a busy node loses its claims",
      "ledger.colour (line " + std::to_string(line_of(6)) + "): unknown key",
  };
  std::string joined;
  for (const auto& line : expected) joined += (joined.empty() ? "" : "\n") + file + line;
  EXPECT_EQ(result.error, joined);
}

TEST_F(LedgerConfigTest, CabledCuttersAndBatching) {
  const std::string table = "[ledger]\nurl = \"postgres://h/db\"\nnode = \"n\"\nshared_dir = \"s\"\n";
  const auto station = load(table + "roles = [\"station\"]\ncutters = [\"a\"]\n");
  ASSERT_TRUE(station.config) << station.error;
  const LedgerConfig& ledger = *station.config->ledger;
  EXPECT_EQ(ledger.cutters, std::vector<std::string>{"a"});
  EXPECT_TRUE(ledger.owns_cutter("a"));
  EXPECT_FALSE(ledger.owns_cutter("b"));
  // Without the list a station owns every cutter of its file; a compute node owns none.
  const auto all = load(table + "roles = [\"station\"]\n");
  ASSERT_TRUE(all.config) << all.error;
  EXPECT_TRUE(all.config->ledger->owns_cutter("a"));
  const auto compute = load(table + "roles = [\"compute\"]\n");
  ASSERT_TRUE(compute.config) << compute.error;
  EXPECT_FALSE(compute.config->ledger->owns_cutter("a"));

  // The ledger's own batch keys of schema 3 and before name the one [batch] rule that replaced them.
  const auto wrong = load(table + "roles = [\"compute\"]\ncutters = [\"z\"]\nbatch_window_s = 2\nmax_batch_jobs = 3\n");
  ASSERT_FALSE(wrong.config);
  const std::string file = (folder_ / "lastcut.toml").string() + ": ";
  EXPECT_EQ(wrong.error,
            file + "ledger.cutters (line " + std::to_string(line_of(5)) +
                "): only a node with the role \"station\" has cutters cabled to it\n" + file +
                "ledger.batch_window_s (line " + std::to_string(line_of(6)) +
                "): no longer read; use [batch] window_s, the same batching rule as on one station"
                " (docs/multi-station.md, upgrading)\n" +
                file + "ledger.max_batch_jobs (line " + std::to_string(line_of(7)) +
                "): no longer read; use [batch] max_pieces (pieces, not jobs), the same batching rule as on one"
                " station (docs/multi-station.md, upgrading)");
  const auto unknown = load(table + "roles = [\"station\"]\ncutters = [\"z\"]\n");
  ASSERT_FALSE(unknown.config);
  EXPECT_EQ(unknown.error, file + "ledger.cutters: \"z\" is not a [cutters.*] table");
}

TEST_F(LedgerConfigTest, WrongTypesAreRefused) {
  const auto result = load("[ledger]\nurl = 5\nnode = \"n\"\nroles = \"compute\"\nshared_dir = \"s\"\nlease_s = \"30\"\n");
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("ledger.url (line " + std::to_string(line_of(1)) + "): must be a text in quotes"),
            std::string::npos)
      << result.error;
  EXPECT_NE(result.error.find("ledger.roles (line " + std::to_string(line_of(3)) +
                              "): must be a list of one or both of \"compute\", \"station\""),
            std::string::npos)
      << result.error;
  EXPECT_NE(result.error.find("ledger.lease_s (line " + std::to_string(line_of(5)) + "): must be a number"),
            std::string::npos)
      << result.error;
}

TEST_F(LedgerConfigTest, LedgerMustBeATable) {
  std::ofstream(folder_ / "lastcut.toml") << "ledger = \"postgresql://h/db\"\n" << kBase;
  const auto result = load_daemon_config(folder_ / "lastcut.toml");
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("ledger (line 1): must be a table [ledger]"),
            std::string::npos)
      << result.error;
}

}  // namespace
}  // namespace lastcut::daemon
