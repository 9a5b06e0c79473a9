#pragma once
// LedgerShop: a whole multi-station shop in a scratch folder, for tests of several real lastcutd
// nodes on one PostgreSQL job ledger (docs/multi-station.md): one PostgreSQL server and one
// mosquitto broker started by the test on 127.0.0.1, a shared folder, simulated cutters on
// pseudo-terminals (lastcut-sim), and per node a configuration file, watch folder, spool and log.
//
// Every node's file lists every cutter, as a shop's files do; only the node a cutter is cabled to
// gets its real port, the others a path where nothing exists (a node never opens a cutter that is
// not cabled to it, so a node that did would fail to, and its log would say so).
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "tests/daemon/daemon_harness.hpp"
#include "tests/support/mosquitto_broker.hpp"
#include "tests/support/postgres_server.hpp"

namespace lastcut::daemon::testing {

struct ShopCutter {
  std::string name;
  std::string protocol;  // "hpgl" (a plotter, XON/XOFF) or "grbl" (a table)
  std::string station;   // the node it is cabled to
  double timeout_s = 20; // silence before the station gives a cut up (longer than any pause the test makes)
};

struct ShopNode {
  std::string name;
  std::vector<std::string> roles;  // "compute", "station"
};

struct ShopOptions {
  std::vector<ShopNode> nodes;
  std::vector<ShopCutter> cutters;     // the first one is [jobs] default_cutter
  double lease_s = 2.5;
  double heartbeat_s = 0.5;
  double batch_window_s = 1;  // [batch] window_s
  int max_pieces = 8;           // [batch] max_pieces: about 4 jobs of 2 molds
  std::string duplicate_policy = "skip";  // [jobs] duplicate_policy
  std::string extra_paths;   // more [paths] keys for every node (e.g. hides = "hides")
  std::string extra_config;  // more tables for every node (e.g. a [materials.leather] of kind "hide")
  std::string web_token;     // not "": every node serves its operator page, this token may act
};

class LedgerShop {
 public:
  LedgerShop(const std::string& name, ShopOptions options);
  ~LedgerShop();
  LedgerShop(const LedgerShop&) = delete;
  LedgerShop& operator=(const LedgerShop&) = delete;

  // Starts PostgreSQL (database "lastcut") and the broker, then writes every node's configuration
  // (it names both). "" on success, else why not.
  std::string start_services();
  lastcut::test::PostgresServer& postgres() { return postgres_; }
  lastcut::test::MosquittoBroker& broker() { return *broker_; }
  const std::string& url() const { return url_; }

  const std::filesystem::path& root() const { return root_; }
  std::filesystem::path shared_dir() const { return root_ / "shared"; }
  std::filesystem::path node_dir(const std::string& node) const { return root_ / node; }
  std::filesystem::path watch(const std::string& node) const { return node_dir(node) / "incoming"; }
  std::filesystem::path spool(const std::string& node) const { return node_dir(node) / "spool"; }
  std::filesystem::path config_file(const std::string& node) const { return node_dir(node) / "lastcut.toml"; }
  std::filesystem::path log_file(const std::string& node) const { return node_dir(node) / "lastcutd.log"; }
  // The last `chars` characters of every node's log, for failure messages.
  std::string log_tails(std::size_t chars = 3000) const;
  // The port of `node`'s operator page (ShopOptions::web_token), chosen when the services start.
  int web_port(const std::string& node) const { return web_ports_.at(node); }

  // Starts the simulator of `cutter` (again), recording into a folder of its own per run;
  // `fault` is lastcut-sim's --fault (e.g. "stall-at-line=20"). "" on success, else why not.
  std::string start_cutter(const std::string& cutter, const std::string& fault = "");
  void stop_cutter(const std::string& cutter);  // SIGTERM: the simulator writes its record
  // What `cutter` received, per run in order (after stop_cutter).
  std::vector<std::string> received_per_run(const std::string& cutter) const;
  std::string received(const std::string& cutter) const;  // all runs, concatenated

  // Starts lastcutd on `node`'s configuration and waits for "lastcutd ready" in its log (which is
  // appended across restarts). "" on success, else the log.
  std::string start_node(const std::string& node);
  void kill_node(const std::string& node);                         // SIGKILL
  void signal_node(const std::string& node, int signal);           // e.g. SIGHUP: reload
  int stop_node(const std::string& node, double timeout_s = 60);   // SIGTERM; the exit status (-1: timeout)
  bool node_running(const std::string& node);

  // Ledger rows over a connection of the test's own (an independent look at the ledger); throws
  // when the server cannot be reached.
  std::vector<std::vector<std::string>> rows(const std::string& sql) const;
  // The first column of the first row ("" for none or NULL); "" also while the server is unreachable
  // (for polling).
  std::string value(const std::string& sql) const;
  long long count(const std::string& sql) const;  // value() as a number, -1 while unreachable

 private:
  std::string node_config(const ShopNode& node) const;
  const ShopCutter& cutter(const std::string& name) const;

  std::filesystem::path root_;
  ShopOptions options_;
  lastcut::test::PostgresServer postgres_;
  std::unique_ptr<lastcut::test::MosquittoBroker> broker_;
  std::string url_;
  std::map<std::string, std::unique_ptr<Process>> nodes_;
  std::map<std::string, std::unique_ptr<Process>> simulators_;
  std::map<std::string, int> runs_;  // simulator runs per cutter
  std::map<std::string, int> web_ports_;
};

}  // namespace lastcut::daemon::testing
