#pragma once
// One lastcutd station under test, on either store: its own spool folder (DaemonRig) or the shop's
// PostgreSQL ledger (LedgerShop with one node, compute + station, PostgreSQL and mosquitto started
// by the test). The shared behaviour suite (station_behaviour_test.cpp) runs each behaviour against
// both through this one interface, so the two stores cannot drift apart unseen.
// Job states are read the store's own way (state.json files, ledger rows) and given in one vocabulary:
// computing, computed, batched, sending, done, held, failed, skipped.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace lastcut::daemon::testing {

enum class StoreKind { Spool, Ledger };

struct StationSettings {
  std::string duplicate_policy = "skip";
  double window_s = 0;  // [batch]
  int max_pieces = 0;
  bool hides = false;   // a hides folder and a hide material "leather" for cutter-1
  std::string cutter_fault;  // lastcut-sim --fault of cutter-1's first run (e.g. "stall-at-line=20")
};

// A batch of one job for cutter-1 written into the store by the test, not by this lastcutd's run
// (as a crash, another program or a vanished node leaves one): see StationUnderTest::leave_batch.
enum class LeftBatch {
  Queued,     // queued for cutter-1, a well-formed record: it is cut
  Untrusted,  // spool: batch.json with the unknown stage 'xyz'; ledger: `sending` under the lease of a
              // node "station-gone" that ran out (the ledger's CHECK constraints allow no unknown state)
};

struct SeenJob {
  std::string id, scan, state, reason, batch;  // batch "" while in none
};

class StationUnderTest {
 public:
  static std::unique_ptr<StationUnderTest> make(StoreKind kind, const std::string& name, const StationSettings& settings);
  virtual ~StationUnderTest() = default;

  // Starts the simulated cutter-1 (HPGL), the services of the store and lastcutd. "" or why not.
  virtual std::string start() = 0;
  virtual std::filesystem::path watch() const = 0;
  virtual std::filesystem::path hides() const = 0;
  virtual std::filesystem::path config_file() const = 0;
  virtual std::string log() const = 0;
  virtual std::vector<SeenJob> jobs() const = 0;
  // The state of the hide named `hide_id`: loaded (on its table, waiting), nesting, used (nested
  // and cut or queued), empty; "" when the store does not know it.
  virtual std::string hide_state(const std::string& hide_id) const = 0;
  // The state of batch `batch` (an id as in SeenJob::batch): nesting, queued, claimed, sending, cut,
  // held, and dissolved (ledger) or abandoned, empty (spool); "" when the store does not know it.
  virtual std::string batch_state(const std::string& batch) const = 0;
  // The bytes of the cut file the store keeps for `batch` (what cutter-1 is sent), "" if none.
  virtual std::string cut_file(const std::string& batch) const = 0;
  virtual void signal(int signal) = 0;
  virtual int stop() = 0;  // SIGTERM; the exit status
  virtual void kill() = 0;  // SIGKILL: lastcutd writes nothing on its way out
  // Starts lastcutd again on the same store (its recovery runs), after stop() or kill(). "" or why not.
  virtual std::string restart() = 0;
  // cutter-1's simulator: stops the running one (its record is kept) and starts a new run with
  // `fault` ("" none). "" or why not. start() starts the first run (with StationSettings::cutter_fault).
  virtual std::string start_cutter(const std::string& fault = "") = 0;
  virtual void stop_cutter() = 0;  // SIGTERM: the simulator writes its record
  // What cutter-1 received, per simulator run in order; a run's bytes are complete once it stopped.
  virtual std::vector<std::string> received_per_run() const = 0;
  // Writes a batch of one job (its scan named `scan`, cut file `cut_program`) into the store, as
  // `kind` says; lastcutd must not be running (the spool reads such records at start). The batch's id.
  virtual std::string leave_batch(LeftBatch kind, const std::string& scan, const std::string& cut_program) = 0;

  // The job of `scan` (the newest with that name), or a job with empty fields.
  SeenJob job(const std::string& scan) const;
  // `lastcut requeue ID` against this station's configuration; its exit status.
  int requeue(const std::string& job_id) const;
  // What `lastcut status` prints (text) against this station's configuration; a failure if it exits
  // with an error.
  std::string status() const;
  // A small generated last (EU size 40, left) with bytes of its own (`tag`), dropped as `name`
  // with a sidecar (`ticket`: TOML lines, may be "").
  void drop_scan(const std::string& name, const std::string& tag, const std::string& ticket = "") const;
  // Exactly the bytes of an earlier drop (`as` its name now).
  void drop_copy(const std::string& tag, const std::string& as, const std::string& ticket = "") const;
  // Replaces `from` by `to` in the configuration file (a reload test changes one value).
  void edit_config(const std::string& from, const std::string& to) const;
};

}  // namespace lastcut::daemon::testing
