#include "daemon/ledger_node/shared_store.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>

#include "engine/core/durable_file.hpp"

namespace lastcut::daemon {

Status SharedStore::prepare() const {
  for (const char* sub : {"scans", "references", "jobs", "hides", "batches"}) {
    std::error_code error;
    std::filesystem::create_directories(root_ / sub, error);
    if (error) return Status::failure("shared folder " + (root_ / sub).string() + " cannot be created: " + error.message());
  }
  const std::filesystem::path probe = root_ / ("probe-" + std::to_string(::getpid()));
  if (Status written = write_file_durably(probe, "lastcut"); !written) {
    return Status::failure("shared folder " + root_.string() + " is not writable: " + written.error());
  }
  std::error_code ignored;
  std::filesystem::remove(probe, ignored);
  return Status::success();
}

std::filesystem::path SharedStore::scan(const std::string& sha256, const std::string& scan_name) const {
  std::string extension = std::filesystem::path(scan_name).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return root_ / "scans" / (sha256 + extension);
}

std::string SharedStore::relative(const std::filesystem::path& path) const {
  return path.lexically_relative(root_).generic_string();
}

Result<std::filesystem::path> SharedStore::scratch_for(const std::filesystem::path& final,
                                                       const std::string& node) const {
  static std::atomic<long> counter{0};  // scratch folders of this process's threads never collide
  const std::filesystem::path scratch = final.parent_path() / (final.filename().string() + ".part-" + node + "-" +
                                                               std::to_string(::getpid()) + "-" +
                                                               std::to_string(++counter));
  std::error_code error;
  std::filesystem::remove_all(scratch, error);
  std::filesystem::create_directories(scratch, error);
  if (error) return Status::failure("scratch folder " + scratch.string() + " cannot be made: " + error.message());
  return scratch;
}

Status SharedStore::publish(const std::filesystem::path& scratch, const std::filesystem::path& final) const {
  if (Status synced = fsync_folder(scratch); !synced) return synced;
  std::error_code error;
  std::filesystem::rename(scratch, final, error);
  if (error) {
    // rename() over a non-empty folder fails: another node published the same result first.
    std::error_code ignored;
    if (std::filesystem::is_directory(final, ignored)) {
      std::filesystem::remove_all(scratch, ignored);
      return Status::success();
    }
    return Status::failure(final.string() + " cannot be put in place: " + error.message());
  }
  return fsync_folder(final.parent_path());
}

}  // namespace lastcut::daemon
