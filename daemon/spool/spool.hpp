#pragma once
// Spool: the on-disk queue of jobs, modelled on print-shop hot folders, Postfix and CUPS.
// Folders are states, moves are atomic renames followed by fsync of both folders:
//
//   <root>/work/ID/      claimed and in progress (state.json says how far)
//   <root>/done/ID/      cut (or skipped duplicate): scan, molds, report.json, preview.svg, cut file
//   <root>/failed/ID/    bad input: the original scan and the reason
//   <root>/held/ID/      needs an operator (interrupted while cutting, cutter fault, duplicate on hold)
//   <root>/batches/BID/  one nesting of molds from several jobs for one material and cutter
//
// Nothing is ever deleted by the daemon. Thread-safe: different threads may move different jobs.
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "daemon/job/job_state.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

enum class JobFolder { Work, Done, Failed, Held };
std::string folder_name(JobFolder folder);

class Spool {
 public:
  explicit Spool(std::filesystem::path root);

  // Creates the folders; fails when the spool cannot be used.
  Status prepare() const;

  const std::filesystem::path& root() const { return root_; }
  std::filesystem::path job_dir(JobFolder folder, const std::string& id) const;
  std::filesystem::path batch_dir(const std::string& batch_id) const;

  // Moves the scan (and its sidecar, when given) into a new work/ID folder whose state.json is
  // `state` with a fresh id; returns that id. On failure the scan stays where it was.
  // Crash-safe: a work folder without its scan is undone at recovery.
  Result<std::string> claim(const std::filesystem::path& scan, const std::filesystem::path& sidecar, JobState state);

  std::optional<JobState> read_state(JobFolder folder, const std::string& id) const;
  Status write_state(JobFolder folder, const JobState& state) const;
  // Writes the state in its current folder, then renames the job folder to `to`.
  Status move_job(JobFolder from, JobFolder to, const JobState& state) const;
  // Where a job is now, if anywhere.
  std::optional<JobFolder> locate(const std::string& id) const;
  // Ids in a folder, oldest first (ids sort by claim time).
  std::vector<std::string> list(JobFolder folder) const;

  std::string new_batch_id();
  std::optional<BatchState> read_batch(const std::string& batch_id) const;
  Status write_batch(const BatchState& batch) const;
  std::vector<std::string> list_batches() const;

  // Called after every successful write of a job's state.json (live status); set before the
  // spool is shared between threads. The listener must be thread-safe and must not block.
  void on_job_written(std::function<void(const JobState&)> listener) { job_written_ = std::move(listener); }

 private:
  std::string new_job_id();

  std::filesystem::path root_;
  std::function<void(const JobState&)> job_written_;
  std::mutex id_mutex_;
  std::string last_id_second_;
  int id_sequence_ = 0;
};

}  // namespace lastcut::daemon
