#include "daemon/spool/spool.hpp"

#include <algorithm>
#include <ctime>
#include <fstream>

#include "engine/core/durable_file.hpp"

namespace lastcut::daemon {
namespace {

constexpr const char* kStateFile = "state.json";
constexpr const char* kBatchFile = "batch.json";

std::optional<nlohmann::json> read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  if (json.is_discarded()) return std::nullopt;
  return json;
}

std::string utc_second_stamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", &utc);
  return text;
}

std::vector<std::string> sorted_entries(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;  // temporary and hidden names are unfinished
    if (it->is_directory(error)) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

std::string folder_name(JobFolder folder) {
  switch (folder) {
    case JobFolder::Work: return "work";
    case JobFolder::Done: return "done";
    case JobFolder::Failed: return "failed";
    case JobFolder::Held: return "held";
  }
  return "?";
}

Spool::Spool(std::filesystem::path root) : root_(std::move(root)) {}

Status Spool::prepare() const {
  for (const char* name : {"work", "done", "failed", "held", "batches"}) {
    std::error_code error;
    std::filesystem::create_directories(root_ / name, error);
    if (error) return Status::failure("cannot create spool folder " + (root_ / name).string() + ": " + error.message());
  }
  return fsync_folder(root_);
}

std::filesystem::path Spool::job_dir(JobFolder folder, const std::string& id) const {
  return root_ / folder_name(folder) / id;
}

std::filesystem::path Spool::batch_dir(const std::string& batch_id) const { return root_ / "batches" / batch_id; }

std::string Spool::new_job_id() {
  std::lock_guard lock(id_mutex_);
  for (;;) {
    const std::string second = utc_second_stamp();
    if (second != last_id_second_) {
      last_id_second_ = second;
      id_sequence_ = 0;
    }
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, "-%03d", ++id_sequence_);
    std::string id = second + suffix;
    // A restarted daemon may reuse a second already used before the restart.
    if (!locate(id) && !std::filesystem::exists(batch_dir("B" + id))) return id;
  }
}

std::string Spool::new_batch_id() { return "B" + new_job_id(); }

Result<std::string> Spool::claim(const std::filesystem::path& scan, const std::filesystem::path& sidecar,
                                 JobState state) {
  state.id = new_job_id();
  state.scan_name = scan.filename().string();
  state.sidecar_name = sidecar.empty() ? "" : sidecar.filename().string();
  state.claimed_at = utc_now_iso();
  state.advance(state.stage, "taken from the watch folder");
  const std::filesystem::path dir = job_dir(JobFolder::Work, state.id);
  std::error_code error;
  std::filesystem::create_directory(dir, error);
  if (error) return Status::failure("cannot create " + dir.string() + ": " + error.message());
  // Undoes the claim so far; a folder that cannot be removed is an unfinished claim for recovery.
  const auto undo = [&](const Status& failure) -> Status {
    std::filesystem::remove_all(dir, error);
    if (error) return Status::failure(failure.error() + "; " + dir.string() + " left for recovery: " + error.message());
    return failure;
  };
  if (Status written = write_state(JobFolder::Work, state); !written) return undo(written);
  // Sidecar first: once the scan is moved the job counts as claimed, and recovery finds the
  // sidecar either still beside the scan's old place or already in the job folder.
  if (!sidecar.empty()) {
    if (Status moved = move_durably(sidecar, dir / sidecar.filename()); !moved) return undo(moved);
  }
  if (Status moved = move_durably(scan, dir / scan.filename()); !moved) {
    if (!sidecar.empty()) {
      // The sidecar stays in the job folder: keep the folder, recovery hands it back.
      if (Status back = move_durably(dir / sidecar.filename(), sidecar); !back) {
        return Status::failure(moved.error() + "; the sidecar stays in " + dir.string() + " for recovery: " + back.error());
      }
    }
    return undo(moved);
  }
  return state.id;
}

std::optional<JobState> Spool::read_state(JobFolder folder, const std::string& id) const {
  auto json = read_json(job_dir(folder, id) / kStateFile);
  if (!json) return std::nullopt;
  return job_state_from_json(*json);
}

Status Spool::write_state(JobFolder folder, const JobState& state) const {
  Status written = write_file_durably(job_dir(folder, state.id) / kStateFile, to_json(state).dump(2) + "\n");
  if (written && job_written_) job_written_(state);
  return written;
}

Status Spool::move_job(JobFolder from, JobFolder to, const JobState& state) const {
  if (Status written = write_state(from, state); !written) return written;
  if (from == to) return Status::success();
  return move_durably(job_dir(from, state.id), job_dir(to, state.id));
}

std::optional<JobFolder> Spool::locate(const std::string& id) const {
  for (JobFolder folder : {JobFolder::Work, JobFolder::Done, JobFolder::Failed, JobFolder::Held}) {
    std::error_code error;
    if (std::filesystem::is_directory(job_dir(folder, id), error)) return folder;
  }
  return std::nullopt;
}

std::vector<std::string> Spool::list(JobFolder folder) const { return sorted_entries(root_ / folder_name(folder)); }

std::optional<BatchState> Spool::read_batch(const std::string& batch_id) const {
  auto json = read_json(batch_dir(batch_id) / kBatchFile);
  if (!json) return std::nullopt;
  return batch_state_from_json(*json);
}

Status Spool::write_batch(const BatchState& batch) const {
  return write_file_durably(batch_dir(batch.id) / kBatchFile, to_json(batch).dump(2) + "\n");
}

std::vector<std::string> Spool::list_batches() const { return sorted_entries(root_ / "batches"); }

}  // namespace lastcut::daemon
