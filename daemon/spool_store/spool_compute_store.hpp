#pragma once
// SpoolComputeStore: the compute pool's store on one station's spool (station/compute_store.hpp).
// The main thread hands it ids (a claimed job to compute, a closed batch or a loaded hide to nest);
// a worker's claim reads the job's or batch's state from the spool, the truth, and skips what an
// operator or an earlier turn moved on meanwhile. A job's molds go into work/ID, a batch's layout and
// cut file into batches/BID; every outcome is a set_job_stage (job_outcomes.hpp).
// Attempts are counted on disk before the molds are computed: a scan that crashes lastcutd
// max_attempts times fails instead of being computed forever.
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "daemon/config/daemon_config.hpp"
#include "daemon/spool/spool.hpp"
#include "daemon/station/compute_store.hpp"

namespace lastcut::daemon {

class SpoolComputeStore : public ComputeStore {
 public:
  struct Listeners {
    // A job now waits for a batch or a hide (computed, or back from a hide it did not fit on).
    std::function<void(const std::string& job_id)> computed;
    // A nested batch is queued for its cutter.
    std::function<void(const BatchState& batch)> queued;
  };
  SpoolComputeStore(const Spool& spool, std::function<std::shared_ptr<const DaemonConfig>()> settings,
                    Listeners listeners);

  // A job in work/ whose molds are to be made (stage claimed).
  void add_job(const std::string& job_id);
  // A batch in batches/ to nest (stage nesting): a strip batch or a hide.
  void add_batch(const std::string& batch_id);
  // Jobs and batches not yet claimed.
  std::size_t waiting() const;
  // Forgets what is not claimed yet (it stays in the spool; recovery finds it at the next start).
  void clear();

  Result<std::optional<ComputeClaim>> claim(const std::string& worker) override;

 private:
  struct Entry {
    bool is_batch = false;
    std::string id;
  };
  std::unique_ptr<MoldsClaim> claim_job(const std::string& job_id);
  std::unique_ptr<NestClaim> claim_batch(const std::string& batch_id);

  const Spool& spool_;
  std::function<std::shared_ptr<const DaemonConfig>()> settings_;
  Listeners listeners_;
  mutable std::mutex mutex_;
  std::deque<Entry> entries_;
};

}  // namespace lastcut::daemon
