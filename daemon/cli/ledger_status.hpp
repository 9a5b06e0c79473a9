#pragma once
// `lastcut status` and `lastcut requeue ID` on a node whose configuration has [ledger]: they read
// and write the shared PostgreSQL ledger (docs/multi-station.md) instead of the local spool, so
// they show and act on the whole shop from any node.
#include <cstddef>
#include <string>

namespace lastcut::cli {

// Both return false (and do nothing) when the configuration has no [ledger] or a spool folder
// was given with --spool: the caller then works on the file spool as before. When they return
// true, exit_code is set (0, or non-zero after one line on stderr).
bool ledger_status(const std::string& config_file, const std::string& spool_dir, std::size_t recent_count, bool as_json,
                   int& exit_code);
bool ledger_requeue(const std::string& config_file, const std::string& spool_dir, const std::string& job_id,
                    int& exit_code);

}  // namespace lastcut::cli
