#include "daemon/station/station.hpp"

#include <spdlog/spdlog.h>

namespace lastcut::daemon {
Station::Station(std::shared_ptr<const DaemonConfig> config,
                 const std::function<std::unique_ptr<StationStore>(const RunningConfig&)>& make_store,
                 const CutterPauses* pauses)
    : config_(std::move(config)), pauses_(pauses), store_(make_store(config_)) {}

Station::~Station() { stop(); }

Status Station::start() {
  const auto settings = config_.get();  // one configuration for the whole start (SIGHUP may replace it)
  StationLinks links;
  links.observer = observer_;
  links.wake_compute = [this] {
    if (compute_pool_) compute_pool_->wake();
  };
  links.wake_cutter = [this](const std::string& name) {
    for (const auto& cutter : cutters_)
      if (cutter->name() == name) cutter->wake();
  };
  links.cutter_condition = [this](const std::string& name) {
    for (const auto& cutter : cutters_)
      if (cutter->name() == name) return cutter->condition();
    return std::string("not started");
  };
  links.files_being_checked = [this] { return scans_ ? scans_->folder().pending_count() : std::size_t{0}; };
  // 1. The store: storage prepared, what an earlier run left put right, before any file is taken.
  started_ = true;
  if (Status opened = store_->open(links); !opened) return opened;
  // 2. The folders files are dropped into.
  auto scan_folder = std::make_unique<HotFolder>(settings->paths.watch_dir, settings->watch);
  if (Status watching = scan_folder->start(); !watching) return watching;
  scans_ = std::make_unique<FolderIntake>(std::move(scan_folder),
                                          [this](const ReadyScan& ready) { return store_->take_scan(ready); });
  if (!settings->paths.hides_dir.empty()) {
    auto hide_folder = std::make_unique<HotFolder>(settings->paths.hides_dir, settings->watch, HotFolderContent::Hides);
    if (Status watching = hide_folder->start(); !watching) return watching;
    spdlog::info("hides folder {} ({}): hides dropped here lie on their cutter's table",
                 settings->paths.hides_dir.string(), hide_folder->mode_description());
    hides_ = std::make_unique<FolderIntake>(std::move(hide_folder),
                                            [this](const ReadyScan& ready) { return store_->take_hide(ready); });
  }
  // 3. A worker for each cutter cabled here.
  for (const StationCutter& place : store_->cutters()) {
    auto worker = std::make_unique<CutterWorker>(place.name, *place.store, monitor_,
                                                 [this, name = place.name] { return config_.cutter_section(name); });
    if (observer_) {
      worker->on_status([observer = observer_](const CutterStatus& status) { observer->cutter_changed(status); });
    }
    worker->set_pauses(pauses_);
    worker->start(place.first);
    cutters_.push_back(std::move(worker));
  }
  // 4. The compute workers, last: what they finish wakes the cutters, which must exist by then.
  if (ComputeStore* compute = store_->compute_store()) {
    compute_pool_ = std::make_unique<ComputePool>(*compute, monitor_, [this] { return config_.get(); },
                                                  store_->compute_timing());
    compute_pool_->observe(observer_);
    compute_pool_->start(settings->jobs.compute_workers);
  }
  spdlog::info("watching {} ({}); {}; {} compute worker(s); {} cutter(s); duplicates: {}",
               settings->paths.watch_dir.string(), scans_->folder().mode_description(), store_->where(),
               compute_pool_ ? settings->jobs.compute_workers : 0, cutters_.size(),
               to_string(settings->jobs.duplicate_policy));
  return Status::success();
}

void Station::tick(Clock::time_point now) {
  if (stopped_ || !scans_) return;
  scans_->take_ready(now);
  if (hides_) hides_->take_ready(now);
  store_->tick(now);
}

int Station::event_fd() const { return scans_ ? scans_->folder().event_fd() : -1; }

void Station::read_events() {
  if (scans_) scans_->folder().read_events();
  if (hides_) hides_->folder().read_events();  // its events are read here; tick() runs every 100 ms anyway
}

std::string Station::status_line() const {
  std::string line = store_->status_line();
  for (const auto& cutter : cutters_) line += "; " + cutter->name() + ": " + cutter->condition();
  return line;
}

std::string Station::reload(std::shared_ptr<const DaemonConfig> next) { return config_.reload(*next); }

void Station::stop() {
  if (!started_ || stopped_) return;
  stopped_ = true;
  // The reverse of start: no more work is claimed, each computation in hand finishes, then each cut
  // in hand gets its grace time.
  store_->stopping();
  if (compute_pool_) compute_pool_->stop();
  std::vector<CutterWorker*> workers;
  for (const auto& cutter : cutters_) workers.push_back(cutter.get());
  stop_cutter_workers(workers, config_.get()->jobs.stop_grace_s);
  cutters_.clear();
  compute_pool_.reset();
  store_->close();
  scans_.reset();
  hides_.reset();
}

}  // namespace lastcut::daemon
