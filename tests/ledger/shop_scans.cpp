// The scans of the three-node test (see shop_scans.hpp).
#include "tests/ledger/shop_scans.hpp"

#include <sstream>

#include <gtest/gtest.h>

#include "tests/daemon/daemon_rig.hpp"

namespace lastcut::daemon::testing {

std::vector<ShopScan> plan_scans(int count) {
  std::vector<ShopScan> scans;
  for (int i = 0; i < count; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "scan-%02d.stl", i);
    ShopScan scan{name, i % 2 == 0 ? "cutter-b" : "cutter-a", "", {}, i < 36 ? 1 : i < 48 ? 2 : 3};
    if (i % 4 != 3) scan.sidecar = "cutter = \"" + scan.cutter + "\"\norder = \"O-" + std::to_string(i) + "\"\n";
    const std::string home = scan.wave == 2 || (i / 2) % 2 == 1 ? "station-b" : "station-a";
    scan.nodes = {home};
    if (i % 10 == 5 || i % 12 == 6) scan.nodes.push_back(home == "station-a" ? "station-b" : "station-a");
    scans.push_back(scan);
  }
  return scans;
}

void make_scans(const std::vector<ShopScan>& scans, const std::filesystem::path& staging) {
  const std::vector<std::filesystem::path> lasts = {small_last(40, "left", 1), small_last(41, "right", 2),
                                                    small_last(39, "left", 3)};
  std::filesystem::create_directories(staging);
  for (std::size_t i = 0; i < scans.size(); ++i) write_variant(lasts[i % 3], staging / scans[i].name, scans[i].name);
}

int drop_wave(LedgerShop& shop, const std::vector<ShopScan>& scans, const std::filesystem::path& staging, int wave) {
  int files = 0;
  for (const ShopScan& scan : scans) {
    if (scan.wave != wave) continue;
    const std::string sidecar = std::filesystem::path(scan.name).stem().string() + ".job.toml";
    if (!scan.sidecar.empty()) write_text(staging / sidecar, scan.sidecar);
    for (const std::string& node : scan.nodes) {
      if (!scan.sidecar.empty()) drop(staging / sidecar, shop.watch(node), sidecar);
      drop(staging / scan.name, shop.watch(node), scan.name);
      ++files;
    }
  }
  return files;
}

int count_scans_in(const std::filesystem::path& folder) {
  int count = 0;
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name[0] != '.' && name.find(".stl") != std::string::npos) ++count;
  }
  return count;
}

std::map<std::string, std::string> sha256_of(const std::vector<ShopScan>& scans, const std::filesystem::path& staging) {
  std::vector<std::string> argv = {"/usr/bin/sha256sum"};
  for (const ShopScan& scan : scans) argv.push_back((staging / scan.name).string());
  const auto out = staging / "sha256.txt";
  std::filesystem::remove(out);
  EXPECT_EQ(run_command(argv, out), 0) << read_text(out);
  std::map<std::string, std::string> hashes;
  std::istringstream lines(read_text(out));
  for (std::string hash, path; lines >> hash >> path;) hashes[std::filesystem::path(path).filename().string()] = hash;
  return hashes;
}

}  // namespace lastcut::daemon::testing
