#pragma once
// PostgresServer: a real PostgreSQL 15 server of its own for a test, in a temporary folder
// (initdb + pg_ctl), listening on 127.0.0.1 on a free port and on a socket in that folder; stopped
// and removed by the destructor. Tests run as root in CI and initdb refuses root, so as root the
// server runs as the `postgres` system user (created by the postgresql package) with the folder
// handed to it. Nothing is skipped: when the server cannot start, start() says why and the test
// fails with that reason (a missing install step must fail the suite).
#include <filesystem>
#include <string>
#include <vector>

namespace lastcut::test {

class PostgresServer {
 public:
  // durable = false (tests): fsync off, much faster, nothing survives a power cut. Benchmarks
  // pass true to measure what a shop's server does.
  explicit PostgresServer(bool durable = false) : durable_(durable) {}
  ~PostgresServer();
  PostgresServer(const PostgresServer&) = delete;
  PostgresServer& operator=(const PostgresServer&) = delete;

  // initdb (first call only) and start (again on the same port after stop()); empty on success, else the reason with the server's log.
  std::string start();
  // Stops the server (fast shutdown: open sessions are cut, committed data stays). Empty on success.
  std::string stop();
  bool running() const { return running_; }

  int port() const { return port_; }
  const std::filesystem::path& folder() const { return folder_; }
  // A fresh database for one test; its libpq URL ("postgresql://lastcut@127.0.0.1:PORT/NAME").
  // Empty on failure, with the reason in `error`.
  std::string create_database(const std::string& name, std::string& error);
  std::string url(const std::string& database) const;

 private:
  std::string run(const std::vector<std::string>& argv) const;  // empty on exit 0, else the output
  std::string server_log_tail() const;

  std::filesystem::path folder_;
  int port_ = 0;
  bool running_ = false;
  bool durable_ = false;
};

}  // namespace lastcut::test
