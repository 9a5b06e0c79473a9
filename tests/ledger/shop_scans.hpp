#pragma once
// The scans of the three-node test (tests/ledger/multi_node_test.cpp): which cutter each names in
// its sidecar, which watch folders it is dropped into and when, made from generated lasts with
// bytes of their own.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "tests/ledger/ledger_shop.hpp"

namespace lastcut::daemon::testing {

struct ShopScan {
  std::string name;
  std::string cutter;
  std::string sidecar;             // NAME.job.toml's text; "" for none: the default cutter (cutter-a)
  std::vector<std::string> nodes;  // watch folders it is dropped into (two: the same bytes on both stations)
  int wave = 1;                    // 1 at the start, 2 while PostgreSQL is down, 3 after station-a's restart
};

// `count` scans (count >= 48): even ones name cutter-b in their sidecar, i % 4 == 1 name cutter-a,
// i % 4 == 3 have none (the default, cutter-a). Every other pair goes to station-b, the rest to
// station-a; i % 10 == 5 and i % 12 == 6 are dropped on both. Waves: i < 36, i < 48 (all on
// station-b, since station-a is down then; the duplicates also on station-a), the rest.
std::vector<ShopScan> plan_scans(int count);
// Writes each scan into `staging` (three generated lasts, each file with its own STL header).
void make_scans(const std::vector<ShopScan>& scans, const std::filesystem::path& staging);
// Drops the scans of one wave (sidecar first) into their watch folders; returns the scan files dropped.
int drop_wave(LedgerShop& shop, const std::vector<ShopScan>& scans, const std::filesystem::path& staging, int wave);
// Files of a folder whose name holds ".stl" (scans, not sidecars or reasons).
int count_scans_in(const std::filesystem::path& folder);
// name -> SHA-256 of the staged scans, by sha256sum (an implementation other than the daemon's).
std::map<std::string, std::string> sha256_of(const std::vector<ShopScan>& scans, const std::filesystem::path& staging);

}  // namespace lastcut::daemon::testing
