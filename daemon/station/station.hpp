#pragma once
// Station: lastcutd's job flow, written once for both stores (station_store.hpp). A scan's road:
//
//   watch folder --HotFolder: stable, complete--> store.take_scan (claimed into the store)
//     --ComputePool (compute_pool.hpp) on store.compute_store(): molds, then batches and hides
//     --CutterWorker (cutter_worker.hpp), one per cutter cabled here, on its CutStore--> the cutter
//   hides folder --HotFolder--> store.take_hide (a hide lying on its cutter's table)
//
// What is due between those steps (grouping computed jobs into batches on a spool, the sweep of
// expired leases on a ledger) is the store's tick. The station owns the order of things: start in
// one readable order (the store, the folders, the cutters, the compute pool), the main loop's
// turn, SIGHUP (RunningConfig), and stop in the reverse order.
#include <memory>
#include <string>
#include <vector>

#include "daemon/station/compute_pool.hpp"
#include "daemon/station/config_reload.hpp"
#include "daemon/station/cutter_worker.hpp"
#include "daemon/station/folder_intake.hpp"
#include "daemon/station/job_flow.hpp"
#include "daemon/station/progress_monitor.hpp"
#include "daemon/station/station_store.hpp"

namespace lastcut::daemon {

class Station : public JobFlow {
 public:
  // `make_store` builds the store from the station's running configuration (it outlives the store).
  // `pauses`: the operator's paused cutters (none when null); outlives the station.
  Station(std::shared_ptr<const DaemonConfig> config,
          const std::function<std::unique_ptr<StationStore>(const RunningConfig&)>& make_store,
          const CutterPauses* pauses = nullptr);
  ~Station() override;
  Station(const Station&) = delete;
  Station& operator=(const Station&) = delete;

  void set_observer(StatusObserver* observer) override { observer_ = observer; }
  Status start() override;
  void tick(Clock::time_point now) override;
  int event_fd() const override;
  void read_events() override;
  std::string stuck(Clock::time_point now) const override { return monitor_.stuck(now); }
  std::string status_line() const override;
  // Paths, watch mode, compute workers, the set of cutters and [ledger] need a restart: the
  // returned line says which of those changed and were kept (station/config_reload.hpp).
  std::string reload(std::shared_ptr<const DaemonConfig> config) override;
  void stop() override;

 private:
  RunningConfig config_;
  ProgressMonitor monitor_;
  StatusObserver* observer_ = nullptr;
  const CutterPauses* pauses_ = nullptr;
  std::unique_ptr<StationStore> store_;
  std::unique_ptr<FolderIntake> scans_;
  std::unique_ptr<FolderIntake> hides_;  // null when paths.hides is not set
  std::unique_ptr<ComputePool> compute_pool_;       // null when this node does not compute
  std::vector<std::unique_ptr<CutterWorker>> cutters_;
  bool started_ = false;
  bool stopped_ = false;
};

}  // namespace lastcut::daemon
