// A throw-away PostgreSQL server per test program (see postgres_server.hpp).
#include "tests/support/postgres_server.hpp"

#include "tests/support/child_process.hpp"
#include "tests/support/loopback_port.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <pwd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <pqxx/pqxx>

namespace lastcut::test {
namespace {

namespace fs = std::filesystem;

// The newest installed server (Debian: /usr/lib/postgresql/VERSION/bin); LASTCUT_PG_BINDIR overrides.
fs::path server_bin_dir() {
  if (const char* dir = std::getenv("LASTCUT_PG_BINDIR")) return dir;
  fs::path best;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/usr/lib/postgresql", ec)) {
    const fs::path bin = entry.path() / "bin";
    if (fs::exists(bin / "initdb") && (best.empty() || std::stoi(entry.path().filename()) >
                                                          std::stoi(best.parent_path().filename()))) {
      best = bin;
    }
  }
  return best;
}

bool as_root() { return ::geteuid() == 0; }

}  // namespace

PostgresServer::~PostgresServer() {
  if (running_) (void)stop();
  if (!folder_.empty()) {
    std::error_code ec;
    fs::remove_all(folder_, ec);
  }
}

std::string PostgresServer::run(const std::vector<std::string>& argv) const {
  std::vector<std::string> full;
  if (as_root()) full = {"runuser", "-u", "postgres", "--"};
  full.insert(full.end(), argv.begin(), argv.end());
  const fs::path output = folder_ / "command.out";
  std::error_code ec;
  fs::remove(output, ec);  // the child appends: only this command's output
  // runuser needs no terminal; pg_ctl itself waits at most 60 s (-t 60) for the server.
  int status = -1;
  try {
    status = run_to_exit(full, output, 180);
  } catch (const std::exception& e) {
    return e.what();
  }
  if (status == 0) return "";
  std::ifstream in(output);
  std::stringstream text;
  text << in.rdbuf();
  std::string command;
  for (const std::string& arg : full) command += (command.empty() ? "" : " ") + arg;
  return command + " failed: " + text.str();
}

std::string PostgresServer::server_log_tail() const {
  std::ifstream in(folder_ / "server.log");
  std::stringstream text;
  text << in.rdbuf();
  const std::string log = text.str();
  return log.size() > 2000 ? log.substr(log.size() - 2000) : log;
}

std::string PostgresServer::start() {
  if (running_) return "";
  const fs::path bin = server_bin_dir();
  if (bin.empty()) {
    return "no PostgreSQL server installed (/usr/lib/postgresql/*/bin/initdb): install the Debian package "
           "postgresql (scripts/setup.sh does)";
  }
  if (folder_.empty()) {
    std::string pattern = (fs::temp_directory_path() / "lastcut-pg-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) return "cannot make a temporary folder for PostgreSQL";
    folder_ = pattern;
    if (as_root()) {
      // initdb refuses root: the folder belongs to the postgres system user.
      const passwd* postgres = ::getpwnam("postgres");
      if (!postgres || ::chown(folder_.c_str(), postgres->pw_uid, postgres->pw_gid) != 0) {
        return "cannot hand " + folder_.string() + " to the postgres system user (installed with the Debian "
               "package postgresql, see scripts/setup.sh)";
      }
    }
    if (std::string failed = run({(bin / "initdb").string(), "-D", (folder_ / "data").string(), "-A", "trust", "-U",
                                  "lastcut", "-E", "UTF8", "--locale=C", "--no-sync"});
        !failed.empty()) {
      return failed;
    }
  }
  // A free port may be taken between the probe and the server's bind: try a few.
  std::string last_failure;
  for (int attempt = 0; attempt < 5; ++attempt) {
    // A restart keeps its port (clients reconnect to the same URL) unless someone took it.
    if (port_ == 0 || attempt > 0) port_ = free_loopback_port();
    const std::string options = "-p " + std::to_string(port_) + " -k " + folder_.string() +
                                " -c listen_addresses=127.0.0.1 -c max_connections=60" +
                                (durable_ ? "" : " -c fsync=off -c synchronous_commit=off");
    last_failure = run({(bin / "pg_ctl").string(), "-D", (folder_ / "data").string(), "-l",
                        (folder_ / "server.log").string(), "-w", "-t", "60", "-o", options, "start"});
    if (last_failure.empty()) {
      running_ = true;
      return "";
    }
  }
  return last_failure + "\nserver log:\n" + server_log_tail();
}

std::string PostgresServer::stop() {
  if (!running_) return "";
  running_ = false;
  return run({(server_bin_dir() / "pg_ctl").string(), "-D", (folder_ / "data").string(), "-m", "fast", "-w", "stop"});
}

std::string PostgresServer::url(const std::string& database) const {
  return "postgresql://lastcut@127.0.0.1:" + std::to_string(port_) + "/" + database;
}

std::string PostgresServer::create_database(const std::string& name, std::string& error) {
  try {
    pqxx::connection connection(url("postgres"));
    pqxx::nontransaction tx(connection);
    tx.exec("CREATE DATABASE " + tx.quote_name(name));
    return url(name);
  } catch (const std::exception& e) {
    error = "cannot create database " + name + ": " + e.what();
    return "";
  }
}

}  // namespace lastcut::test
