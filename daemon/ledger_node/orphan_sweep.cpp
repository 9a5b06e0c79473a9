#include "daemon/ledger_node/orphan_sweep.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <spdlog/spdlog.h>

namespace lastcut::daemon {
namespace {

// The batch id a folder name is, or 0 (scratch folders and anything else).
long long batch_id_of(const std::string& name) {
  if (name.empty() || name.size() > 18 || !std::all_of(name.begin(), name.end(), ::isdigit)) return 0;
  return std::stoll(name);
}

}  // namespace

Result<std::vector<std::string>> remove_orphan_batch_folders(ledger::LedgerClient& client, const SharedStore& shared,
                                                             double grace_s) {
  const std::filesystem::path batches = shared.root() / "batches";
  const auto now = std::filesystem::file_time_type::clock::now();
  std::vector<long long> old_enough;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(batches, error)) {
    const long long id = batch_id_of(entry.path().filename().string());
    if (!id || !entry.is_directory(error)) continue;
    const auto modified = entry.last_write_time(error);
    if (error) continue;
    if (std::chrono::duration<double>(now - modified).count() >= grace_s) old_enough.push_back(id);
  }
  if (error) return Status::failure("shared folder " + batches.string() + " cannot be listed: " + error.message());
  std::sort(old_enough.begin(), old_enough.end());
  if (old_enough.empty()) return std::vector<std::string>{};
  const Result<std::vector<long long>> unused = client.batches_without_use(old_enough);
  if (!unused) return unused.status();
  std::vector<std::string> removed;
  for (long long id : *unused) {
    const std::filesystem::path folder = shared.batch_dir(id);
    std::filesystem::remove_all(folder, error);
    if (error) {
      spdlog::error("shared folder: orphaned batch folder {} cannot be removed: {}", folder.string(), error.message());
      error.clear();
      continue;
    }
    spdlog::info("shared folder: batch folder {} removed: no batch in the ledger uses it (its nesting was refused "
                 "or came back empty)",
                 folder.string());
    removed.push_back(std::to_string(id));
  }
  return removed;
}

}  // namespace lastcut::daemon
