// `lastcutd --check-config` with [ledger], the real binary against a real server: it connects,
// reports the schema version in one line and changes nothing; an unreachable ledger or a schema
// newer than the build exits non-zero with one line; a node that cannot reach its ledger does not
// start (rather than silently using the file spool).
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "daemon/ledger/schema.hpp"
#include "tests/ledger/ledger_fixture.hpp"

namespace lastcut::test {
namespace {

struct DaemonRun {
  int exit_code = -1;
  std::string out, err;
};

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class CheckConfigTest : public LedgerTest {
 protected:
  DaemonRun lastcutd(const std::string& option, const std::string& ledger_url) {
    const std::filesystem::path folder = server_.folder();
    const std::filesystem::path config = folder / "lastcut.toml";
    std::ofstream(config) << "[paths]\nwatch = \"in\"\nspool = \"spool\"\nmachines = \"" << LASTCUT_SOURCE_DIR
                          << "/config/machines\"\n[jobs]\ndefault_material = \"calf\"\ndefault_cutter = \"a\"\n"
                             "[materials.calf]\nwidth_mm = 500\nlength_mm = 900\n"
                             "[cutters.a]\nprotocol = \"grbl\"\nport = \"/dev/null\"\nmachine = \"grbl-drag-knife\"\n"
                             "[ledger]\nurl = \""
                          << ledger_url << "\"\nnode = \"station-1\"\nroles = [\"compute\", \"station\"]\n"
                          << "shared_dir = \"shared\"\n";
    const std::string command = std::string("'") + LASTCUT_BINARY_DIR + "/bin/lastcutd' " + option + " '" +
                                config.string() + "' >'" + (folder / "out.txt").string() + "' 2>'" +
                                (folder / "err.txt").string() + "'";
    const int status = std::system(command.c_str());
    DaemonRun run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = read_all(folder / "out.txt");
    run.err = read_all(folder / "err.txt");
    config_ = config.string();
    return run;
  }

  std::string config_;
};

TEST_F(CheckConfigTest, ReportsTheSchemaVersionAndChangesNothing) {
  const std::string known = std::to_string(ledger::known_schema_version());
  DaemonRun fresh = lastcutd("--check-config", url_);
  EXPECT_EQ(fresh.exit_code, 0) << fresh.err;
  EXPECT_NE(fresh.out.find("\nledger " + url_ + ": reachable, no schema yet (version " + known +
                           " is applied at the first start)\n"),
            std::string::npos)
      << fresh.out;
  EXPECT_EQ(query("SELECT to_regclass('schema_version') IS NULL"), "t");  // read only

  ASSERT_TRUE(client("station-1"));
  DaemonRun migrated = lastcutd("--check-config", url_);
  EXPECT_EQ(migrated.exit_code, 0) << migrated.err;
  EXPECT_NE(migrated.out.find("\nledger " + url_ + ": reachable, schema version " + known + " (this lastcutd knows " +
                              known + ")\n"),
            std::string::npos)
      << migrated.out;
}

TEST_F(CheckConfigTest, NewerSchemaAndUnreachableLedgerFailWithOneLine) {
  ASSERT_TRUE(client("station-1"));
  {
    pqxx::connection connection(url_);
    pqxx::work tx(connection);
    tx.exec_params("INSERT INTO schema_version (version, name) VALUES ($1, 'future')",
                   ledger::known_schema_version() + 1);
    tx.commit();
  }
  DaemonRun newer = lastcutd("--check-config", url_);
  EXPECT_EQ(newer.exit_code, 1);
  EXPECT_EQ(newer.err, "ledger " + url_ + ": schema version " + std::to_string(ledger::known_schema_version() + 1) +
                           " is newer than this lastcutd knows (" + std::to_string(ledger::known_schema_version()) +
                           "): update lastcutd on this node\n");

  ASSERT_TRUE(server_.stop().empty());
  DaemonRun down = lastcutd("--check-config", url_);
  EXPECT_EQ(down.exit_code, 1);
  EXPECT_EQ(down.err.rfind("ledger unreachable while connecting to " + url_ + ": ", 0), 0u) << down.err;
  EXPECT_EQ(std::count(down.err.begin(), down.err.end(), '\n'), 1) << down.err;
}

TEST_F(CheckConfigTest, ALedgerNodeThatCannotReachItsLedgerDoesNotStartOnItsOwnSpool) {
  ASSERT_TRUE(server_.stop().empty());
  DaemonRun run = lastcutd("--config", url_);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("lastcutd cannot start: ledger unreachable while connecting to " + url_ + ": "),
            std::string::npos)
      << run.err;
  // Not silently a single station: nothing of the file spool's job flow was set up.
  EXPECT_FALSE(std::filesystem::exists(server_.folder() / "spool" / "work"));
}

}  // namespace
}  // namespace lastcut::test
