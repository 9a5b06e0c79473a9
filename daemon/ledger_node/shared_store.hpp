#pragma once
// SharedStore: the folder every ledger node reaches (NFS or another share), files named by the
// SHA-256 of the scan they come from, so that any node finds them from a ledger row alone:
//
//   scans/<sha256><ext>              the scan's bytes as dropped (.stl, .obj, .ply)
//   references/<sha256>/<copy>       reference patterns its sidecar names (docs/compare.md)
//   jobs/<sha256>/                   molds/, items.json, report.json of that scan
//   hides/<sha256>/                  a hide file as dropped (.dxf or .json) and its sidecar <stem>.toml
//   batches/<id>/                    layout.json, preview.svg, cut.<ext> of ledger batch <id>
//                                    (a hide batch also hide-report.json and offcut.dxf)
//
// Files, not database rows: a scan is megabytes and the database stays small (docs/multi-station.md
// has the figures). A result is written into a private scratch folder beside its place and renamed
// into place only when complete, so a node dying mid-write never leaves a half result under the
// final name. Two nodes computing the same scan (a lease expired mid-way) write the same bytes
// (the engine is deterministic): the first complete folder stays.
#include <filesystem>
#include <string>

#include "engine/core/status.hpp"

namespace lastcut::daemon {

class SharedStore {
 public:
  explicit SharedStore(std::filesystem::path root) : root_(std::move(root)) {}

  // Creates scans/, references/, jobs/, hides/, batches/; fails with one line when the share is not writable.
  Status prepare() const;

  const std::filesystem::path& root() const { return root_; }
  std::filesystem::path scan(const std::string& sha256, const std::string& scan_name) const;
  std::filesystem::path references(const std::string& sha256) const { return root_ / "references" / sha256; }
  std::filesystem::path job_dir(const std::string& sha256) const { return root_ / "jobs" / sha256; }
  std::filesystem::path hide_dir(const std::string& sha256) const { return root_ / "hides" / sha256; }
  std::filesystem::path batch_dir(long long batch_id) const { return root_ / "batches" / std::to_string(batch_id); }
  // A path inside the store as the ledger keeps it ("batches/12/cut.nc"), and back.
  std::string relative(const std::filesystem::path& path) const;
  std::filesystem::path absolute(const std::string& relative) const { return root_ / relative; }

  // An empty private folder for building `final` (named after it, this node and this process).
  Result<std::filesystem::path> scratch_for(const std::filesystem::path& final, const std::string& node) const;
  // Renames the completed scratch folder to `final`, made durable; when `final` already exists (the
  // same result from another node) the scratch folder is removed and the existing one kept.
  Status publish(const std::filesystem::path& scratch, const std::filesystem::path& final) const;

 private:
  std::filesystem::path root_;
};

}  // namespace lastcut::daemon
