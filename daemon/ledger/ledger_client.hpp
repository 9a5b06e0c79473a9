#pragma once
// LedgerClient: one lastcutd node's view of the shared PostgreSQL job ledger (docs/multi-station.md).
//
// Queue rules, all enforced inside PostgreSQL so that any number of nodes may call at once:
//  - a scan enters once: its SHA-256 is unique, enqueue() of known bytes returns the existing job;
//  - claims take the oldest waiting row with FOR UPDATE SKIP LOCKED (two nodes never get the same
//    row, and neither waits for the other) and give the claimer a lease: holder = this node,
//    expires_at = now() + lease_s by the database's clock, epoch = previous epoch + 1;
//  - every later state change runs in one transaction that first locks the lease row and checks
//    holder = me AND epoch = mine (fencing): a node back from a long pause whose lease expired and
//    was claimed again gets "lease lost" and must drop the work;
//  - sweep_expired() (any node runs it) hands expired job leases back to the queue; a batch whose
//    station vanished while `sending` is `held` for an operator, never queued again (at most once).
// Not thread-safe: one client per thread. No method throws; failures are one line. A connection
// found dead is opened again within the call; while the server is down, calls fail with a line
// starting "ledger unreachable" (unreachable() tells such failures apart).
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "daemon/job/job_parts.hpp"
#include "daemon/ledger/schema.hpp"
#include "engine/core/status.hpp"

namespace pqxx {
class connection_base;  // libpqxx 6: the base of every connection type
}  // namespace pqxx

namespace lastcut::ledger {

enum class LeaseKind { Job, Batch };

// What fences a claim: the row's epoch when this node claimed it.
struct Lease {
  LeaseKind kind = LeaseKind::Job;
  long long object_id = 0;
  long long epoch = 0;
};

// A scan as it enters the ledger (its bytes live in the shared folder under scan_sha256).
struct ScanEntry {
  std::string scan_sha256;  // 64 lowercase hex digits
  std::string scan_name;    // file name as dropped, for the operator
  std::string ticket;       // the sidecar's text (TOML or JSON), "" for none
  std::string material;
  std::string cutter;
};

// What enqueue() does with bytes that are already a job ([jobs] duplicate_policy, as on one station).
enum class OnDuplicate {
  Skip,     // no new job: the first one stays (an event `duplicate` on it)
  Hold,     // a new job, `held` for an operator with the reason; `lastcut requeue` processes it
  Process,  // a new job, `ready`: computed and cut again
};

struct Enqueued {
  long long job_id = 0;       // the new job; with OnDuplicate::Skip the first job of these bytes
  bool duplicate = false;     // the same bytes were already a job
  long long duplicate_of = 0; // ... that job (the first of these bytes)
  std::string state;          // the job's state now
  std::string origin;         // the node that enqueued job_id
  std::string reason;         // why held, "" otherwise
};

// The folder of a job's results in the shared folder (jobs/<this>): the scan's SHA-256, and for a
// duplicate processed again (its sidecar may differ) "<sha256>-<job id>".
std::string job_folder_name(const std::string& scan_sha256, long long job_id, long long duplicate_of);

struct JobClaim {
  long long job_id = 0;
  ScanEntry scan;
  std::string job_folder;  // job_folder_name()
  int attempts = 0;  // this claim included
  Lease lease;
};

struct BatchClaim {
  long long batch_id = 0;
  std::string cutter;
  std::string material;
  std::vector<long long> job_ids;  // ascending
  std::vector<std::string> job_folders;  // job_folder_name() of each job_ids entry
  std::vector<std::string> job_names;    // the scan's file name of each job_ids entry
  std::vector<std::string> job_tickets;  // the ticket (JSON text) of each job_ids entry
  std::vector<std::vector<daemon::JobPart>> job_parts;  // the parts of each job_ids entry (jobs.parts)
  std::vector<int> job_part;                            // and which of them is being cut (jobs.part)
  std::string cut_file;            // set once nested: the cut file's path inside the shared folder
  // A hide batch (make_hide_batch): the hide it is nested on; 0 and "" for a strip batch.
  long long hide_id = 0;
  std::string hide_name;  // the hide's ID, as the digitizer or its sidecar gave it
  std::string hide_file;  // the hide file's path inside the shared folder (its sidecar beside it)
  Lease lease;
};

// A hide as it enters the ledger: it lies on `cutter`'s table (its file lives in the shared folder).
struct HideEntry {
  std::string name;       // the hide's ID, unique in the shop
  std::string material;   // a material of kind "hide"
  std::string cutter;
  std::string hide_file;  // path inside the shared folder
  double area_m2 = 0;
};

struct HideRow {
  long long hide_id = 0;
  std::string name, material, cutter, state, reason, entered_by;
  long long batch_id = 0;  // the newest batch nested on it; 0: none
  int pieces = 0;
  double area_m2 = 0, utilisation = 0;  // utilisation of its usable area, 0..1, once nested
};

// What a compute node hands over when a batch is nested (mark_nested).
struct NestedBatch {
  std::string cut_file;                        // path inside the shared folder; "" when every job was rejected
  int pieces = 0;                              // pieces placed
  std::vector<std::pair<long long, std::string>> rejected;  // job id -> why its molds could not be placed
  std::vector<std::pair<long long, std::string>> waiting;   // hides: job id -> why it waits for the next hide
  std::vector<std::pair<long long, std::string>> held;      // not the jobs' fault (the batch could not be made):
                                                            // job id -> why; an operator requeues them
  double utilisation = 0;  // placed piece area / the material's area (a hide: its usable area), 0..1
  std::string reason;  // when nothing is to be cut: why (kept with the dissolved batch and its hide)
  // Jobs the hide took in part (split_over_hides): their parts from now on (split_part), the current
  // one being what the hide took; the event's words.
  struct Split {
    long long job_id = 0;
    std::vector<daemon::JobPart> parts;
    std::string note;
  };
  std::vector<Split> split;
};

// A job held because its station vanished while sending its batch (for the status events).
struct HeldJob {
  long long job_id = 0, batch_id = 0;
  std::string scan_name, ticket, cutter, reason;
};

struct SweepOutcome {
  std::vector<long long> jobs_requeued;   // lease expired while computing: ready again
  std::vector<long long> jobs_failed;     // ... for the max_attempts-th time: failed
  std::vector<long long> batches_requeued;  // claimed, nothing sent yet: queued again
  std::vector<long long> batches_dissolved;  // expired while nesting: their jobs back to `computed`, to be regrouped
  std::vector<long long> batches_held;    // expired while sending: held with their jobs
  std::vector<HeldJob> jobs_held;         // ... those jobs
};

struct JobRow {
  long long job_id = 0;
  std::string scan_name, state, cutter, material, origin, reason, holder;  // holder: "" when unclaimed
  long long batch_id = 0;                                                  // 0: none
  int attempts = 0;
  std::vector<daemon::JobPart> parts;  // a job of several materials (daemon/job/job_parts.hpp)
  int part = 0;                         // the one nested or cut now
};

// One job for the operator's page: where its results are and what happened to it.
struct JobDetail {
  std::string state, reason;
  std::string job_folder;  // job_folder_name(): jobs/<this> in the shared folder
  struct Event {
    std::string at_utc, node, event, detail;  // at: ISO 8601 UTC
  };
  std::vector<Event> history;  // oldest first
};

// A computed job waiting for a strip batch, as make_batch offers it to the batching rule.
struct ComputedJob {
  long long job_id = 0;
  std::string material, cutter;
  int pieces = 1;
  double waited_s = 0;  // since it was computed, by the database's clock
};
// The batching rule (daemon/station/batching_policy.hpp): given the waiting jobs oldest first, the
// jobs of one due batch (one material and cutter), or none when no batch is due.
using BatchChooser = std::function<std::vector<long long>(const std::vector<ComputedJob>&)>;
// The hide rule (daemon/station/hide_policy.hpp): is a loaded hide due, given the computed jobs of
// its material waiting, whether any is still ready or computing, and how long the hide has waited.
using HideDue = std::function<bool(std::size_t computed_waiting, bool still_computing, double hide_waited_s)>;

struct LedgerOverview {
  struct Node {
    std::string name, roles;  // roles "compute,station"
    double heartbeat_age_s = 0;
  };
  struct Cutter {
    std::string name, station;
    long long queued_batches = 0;
  };
  struct QueuedBatch {  // nested, waiting for its cutter: what an operator may still cancel
    long long id = 0;
    std::string cutter;
    long long jobs = 0;
    int pieces = 0;
  };
  std::vector<std::pair<std::string, long long>> jobs_per_state;  // by state name; states without jobs absent
  struct Waiting {  // computed jobs of one material not yet in a batch
    std::string material;
    long long jobs = 0, pieces = 0;
  };
  std::vector<Waiting> computed_per_material;
  std::vector<Node> nodes;
  std::vector<Cutter> cutters;
  std::vector<QueuedBatch> queued_batches;  // oldest first, at most 100
  struct CutBatch {  // cut in the last 24 hours
    long long id = 0;
    std::string cut_at_utc, material;  // ISO 8601 UTC
    long long jobs = 0;
    int pieces = 0;
    double utilisation = 0;
  };
  std::vector<CutBatch> cut_last_24h;  // oldest first, at most 5000
};

class LedgerClient {
 public:
  // Opens a connection to `url` (libpq URL or key=value string) as node `node`.
  static Result<std::unique_ptr<LedgerClient>> connect(const std::string& url, const std::string& node);
  ~LedgerClient();
  LedgerClient(const LedgerClient&) = delete;
  LedgerClient& operator=(const LedgerClient&) = delete;

  const std::string& node() const { return node_; }

  Result<MigrationOutcome> migrate();
  Result<int> schema_version();

  // Announces this node and the cutters cabled to it, and recovers what an earlier run of this
  // node left: its jobs in computation go back to the queue, its claimed batches are queued
  // again (failed at max_attempts, as in sweep_expired), its batches in `sending` are held (the
  // cutter may have cut part of them). Refuses a cutter cabled to another running station.
  Result<SweepOutcome> register_node(const std::vector<std::string>& roles, const std::vector<std::string>& cutters,
                                     int max_attempts);
  Status heartbeat();

  // Enters a scan as a `ready` job; bytes already known are handled by `on_duplicate`.
  Result<Enqueued> enqueue(const ScanEntry& scan, OnDuplicate on_duplicate = OnDuplicate::Skip);
  // The oldest ready job, now `computing` under a lease of lease_s; nullopt when none waits.
  Result<std::optional<JobClaim>> claim_job(double lease_s);
  // Extends a lease by lease_s from now; "lease lost ..." when another node holds it now.
  Status renew(const Lease& lease, double lease_s);
  // The job's molds are in the shared folder: `computed`, with its pieces (molds x quantity) for batching.
  // A job of several materials (daemon/job/job_parts.hpp) gets its parts, and the first part's
  // material, cutter and pieces instead.
  Status mark_computed(const Lease& lease, int pieces = 1, const std::vector<daemon::JobPart>& parts = {});
  Status mark_failed(const Lease& lease, const std::string& reason);
  // Computed, but held for an operator's review (a mold off its reference pattern).
  Status mark_held(const Lease& lease, const std::string& reason);

  // Offers the computed jobs that no other node is batching (oldest computed first) to `choose`,
  // and makes the jobs it chooses one batch that this node nests under a lease of lease_s (state
  // `nesting`), all in one transaction. nullopt when `choose` finds no batch due. Jobs of
  // `hide_materials` are not offered: they wait for a hide.
  Result<std::optional<BatchClaim>> make_batch(const BatchChooser& choose, double lease_s,
                                               const std::vector<std::string>& hide_materials = {});
  // The oldest loaded hide that `due` finds due (state `nesting` now) with up to max_jobs computed
  // jobs of its material, oldest first, in a batch for the hide's cutter that this node nests under
  // a lease of lease_s. nullopt when no hide is due.
  Result<std::optional<BatchClaim>> make_hide_batch(const HideDue& due, int max_jobs, double lease_s);
  // The batch is nested and its cut file written: `queued` for its cutter's station. Rejected jobs
  // are failed with their reason and leave the batch; waiting ones (hides) go back to `computed`
  // with theirs; with none left the batch is `dissolved`. A hide ends `used`, or `empty` when
  // nothing was placed on it.
  Status mark_nested(const Lease& lease, const NestedBatch& nested);
  // The oldest queued batch of a cutter this node owns (of `cutter` only, unless empty), now `claimed`.
  Result<std::optional<BatchClaim>> claim_batch(double lease_s, const std::string& cutter = "");
  // Before the first byte goes to the cutter: from here the batch ends cut or held.
  Status mark_sending(const Lease& lease);
  Status mark_cut(const Lease& lease);
  // The cutter refused the batch before taking any byte (the driver guarantees it): `queued` again.
  Status mark_not_sent(const Lease& lease, const std::string& reason);
  Status hold_batch(const Lease& lease, const std::string& reason);

  // `grace_s`: a lease is taken back only once it has been expired this long, so a live node that
  // just regained the database renews it first (the nodes pass their heartbeat).
  Result<SweepOutcome> sweep_expired(int max_attempts, double grace_s = 0);
  // Of `batch_ids`, those no batch row needs a folder for: no row, or the row `dissolved` (its
  // nesting was refused or came back empty). The sweep of orphaned batch folders asks this.
  Result<std::vector<long long>> batches_without_use(const std::vector<long long>& batch_ids);

  // A hide now lies on its cutter's table, `loaded`. Refused (one line) while a hide of that name is
  // loaded, being nested or used; a hide that was left `empty` may be loaded again.
  Result<long long> enter_hide(const HideEntry& hide);
  // The newest `limit` hides, for `lastcut status`.
  Result<std::vector<HideRow>> recent_hides(int limit);

  // The operator's `lastcut requeue`: a held or failed job goes back to the queue (ready), with
  // a new attempt count. Fails with the reason for a job in any other state.
  Status requeue_held(long long job_id);
  Result<LedgerOverview> overview();
  // One job's state, results folder and history; an error line when there is no such job.
  Result<JobDetail> job_detail(long long job_id);
  // An operator's cancel of a batch that waits for its cutter (`queued`): the batch and its jobs
  // are held with `reason`, in one transaction with the claim's lock, so a station either claimed
  // it first (refused: the batch's state) or never will. The number of jobs held.
  Result<long long> cancel_queued_batch(long long batch_id, const std::string& reason);
  // The newest `limit` jobs (of one state when `state` is not empty), for `lastcut status`.
  Result<std::vector<JobRow>> recent_jobs(int limit, const std::string& state = "");

 private:
  LedgerClient(std::string url, std::string node);
  // A claimed job ends in `state` (failed or held) with the reason, under the fencing check.
  Status end_job(const Lease& lease, const std::string& state, const std::string& reason);
  Status open();
  // Runs `body` in one transaction on a live connection (re-opened if lost); commits when it succeeds.
  template <typename T, typename Body>
  Result<T> transact(const std::string& doing, Body body);

  std::string url_;
  std::string node_;
  std::unique_ptr<pqxx::connection_base> connection_;
};

std::string to_string(LeaseKind kind);

}  // namespace lastcut::ledger
