#pragma once
// ComputeStore: what the compute pool (compute_pool.hpp) needs from the store that keeps the jobs:
// the spool of one station (daemon/spool_store/spool_compute_store.hpp) or the shop's PostgreSQL ledger
// (daemon/ledger_node/ledger_compute_store.hpp). The pool owns the order of things and the engine
// steps (the molds, a strip batch, a hide, each inside the progress monitor's bracket); the store
// owns claiming, where the files go and what each outcome does to the job's state. A fake store
// stands in for both in tests/station/compute_pool_test.cpp.
//
// Computing is AT LEAST ONCE: a claim the store loses (a crash, a lease that ran out) is computed
// again; each finish writes the outcome only when the claim is still the store's.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "daemon/job/job_parts.hpp"
#include "daemon/job/job_ticket.hpp"
#include "daemon/station/job_molds.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

// A job whose molds are to be made.
struct MoldsWork {
  std::filesystem::path scan;     // the scan's bytes
  std::filesystem::path job_dir;  // molds/, items.json and report go here; the reference copies are in it
  JobTicket ticket;
  std::string label;  // "job 17 (left.ply)": log lines, the watchdog's "stuck on"
};

// One job of a batch or a hide, oldest first.
struct NestJob {
  std::string job_id;
  std::filesystem::path job_dir;  // holds items.json (or a part's items file, job_items_path)
  JobTicket ticket;
  std::vector<int> copies;  // the current part's copies of each item, when split over hides (JobPart::copies)
};

// A strip batch or a hide to nest.
struct NestWork {
  std::string label;  // "batch 4", "hide H-1 (batch 4)"
  std::string material, cutter;
  std::vector<NestJob> jobs;        // oldest first
  std::filesystem::path batch_dir;  // layout, preview, cut file (and for a hide its report, offcut) go here
  std::string hide_file;            // a hide: its file's name in batch_dir (sidecar beside it); "" for a strip
  std::string hide_name;            // a hide: its id as the hides folder named it
};

// How a nesting ended, for every job of the work.
struct NestResult {
  Status made = Status::success();  // failure: nothing nested, not the jobs' fault (no profile, a file not written)
  std::vector<std::string> placed;               // job ids on the layout, oldest first
  std::map<std::string, std::string> rejected;   // job id -> why its pieces cannot be placed or read: it fails
  std::map<std::string, std::string> waiting;    // a hide only: job id -> why it waits for the next hide
  std::string cut_file;                          // file name in batch_dir; "" when nothing is cut
  int pieces = 0;                                // pieces placed
  double utilisation = 0;                        // 0..1 (of a hide's usable area)
  int pieces_waiting = 0;                        // a hide only: the pieces left for the next hide
  // A hide only: jobs placed in part (also in `placed`, ticket split_over_hides) -> the copies placed
  // and left; the store makes the rest the job's next part (split_part in job_parts.hpp).
  std::map<std::string, PartSplit> split;
  double took_s = 0;                             // nesting and cut file
};

// A claimed job whose molds are to be made; the worker holds it while it computes.
class MoldsClaim {
 public:
  virtual ~MoldsClaim() = default;
  virtual const MoldsWork& work() const = 0;
  // Writes the outcome: the job computed, held for review or failed with the reason. Failures to
  // write are logged; the claim then goes back as a lost claim would.
  virtual void finish(const JobMolds& molds) = 0;
};

// A claimed strip batch or hide to nest; the worker holds it while it computes.
class NestClaim {
 public:
  virtual ~NestClaim() = default;
  virtual const NestWork& work() const = 0;
  // Writes the outcome: the batch queued for its cutter with its jobs batched, failed or waiting.
  // Failures to write are logged; the claim then goes back as a lost claim would.
  virtual void finish(const NestResult& result) = 0;
};

// One claim of either kind (never null).
using ComputeClaim = std::variant<std::unique_ptr<MoldsClaim>, std::unique_ptr<NestClaim>>;

class ComputeStore {
 public:
  virtual ~ComputeStore() = default;
  // The next job or batch to compute, claimed for `worker`: nullopt when none waits now, an error line
  // when the store cannot be asked (the pool logs it once per change and asks again later). A job
  // the store itself must end first (attempts used up, an unreadable ticket) is ended here and
  // never handed out.
  virtual Result<std::optional<ComputeClaim>> claim(const std::string& worker) = 0;
};

}  // namespace lastcut::daemon
