#pragma once
// The [ledger] table: this node's part in a multi-station shop sharing one PostgreSQL job ledger
// (docs/multi-station.md). Absent, lastcutd runs on its own file spool exactly as before.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lastcut::daemon {

struct LedgerConfig {
  std::string url;                      // libpq URL, "postgresql://user@host:5432/lastcut"
  std::string node;                     // this machine's name in the ledger, unique in the shop
  std::vector<std::string> roles;       // "compute" (flattens, nests) and/or "station" (owns its [cutters.*])
  std::filesystem::path shared_dir;     // scans and outputs by content hash, reached by every node (NFS)
  double lease_s = 30;                  // a claim not renewed this long goes back to the queue
  double heartbeat_s = 5;               // leases and the node's heartbeat are renewed this often
  // The cutters cabled to this node (station role), each a [cutters.X] of the file; empty = all of
  // them. The others are listed only for their machine profiles (a compute node writes their cut files).
  std::vector<std::string> cutters;

  bool owns_cutter(const std::string& cutter) const;

  bool has_role(const std::string& role) const;
};

}  // namespace lastcut::daemon
