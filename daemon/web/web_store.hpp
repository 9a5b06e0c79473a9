#pragma once
// WebStore: what the operator page reads from and asks of the store that keeps the jobs. The
// overview is the StoreView's, the same `lastcut status` prints, on a spool or on the ledger;
// it is read at most every half second however many pages ask, so twenty watching pages cost the
// store what one does. A job's own files are served from the spool by id only.
#include <chrono>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "daemon/config/daemon_config.hpp"
#include "daemon/store_view/store_view.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

class WebStore {
 public:
  explicit WebStore(std::shared_ptr<const DaemonConfig> config);

  // {mode, headline, stations[], cutters[], batches[], queued_batches[], hides[], cut_last_24h[],
  //  waiting_for_hide{}, incoming[], jobs[]}:
  // jobs are {id, state, where, order, scan, reason, list} with list "work", "held" or "recent".
  Result<nlohmann::json> overview();
  // One job: its line of the overview, its state and history, report.json and file names.
  Result<nlohmann::json> job(const std::string& id);
  // A file of a job: "NAME" or "molds/NAME", already checked by safe_name().
  Result<std::filesystem::path> job_file(const std::string& id, const std::string& name);
  // A file of a batch (or a hide cut as one): on a spool in batches/, on a ledger in its shared folder.
  Result<std::filesystem::path> batch_file(const std::string& batch_id, const std::string& name);
  Result<std::string> requeue(const std::string& id);
  // StoreView::cancel_batch: the line, or why not.
  Result<std::string> cancel_batch(const std::string& batch_id, const std::string& who);

 private:
  // The job's record from the view (its folder: on a spool, in the ledger's shared folder).
  Result<JobRecord> record(const std::string& id);

  std::shared_ptr<const DaemonConfig> config_;
  std::mutex mutex_;  // the view's ledger connection serves one request at a time
  std::unique_ptr<StoreView> view_;
  std::optional<nlohmann::json> cached_;
  std::chrono::steady_clock::time_point cached_at_{};
};

}  // namespace lastcut::daemon
