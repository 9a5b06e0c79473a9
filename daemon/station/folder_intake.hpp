#pragma once
// FolderIntake: one folder files are dropped into (the watch folder for scans, the hides folder),
// as a station takes from it: each file the HotFolder finds stable and complete is offered to the
// store once. Taken (in the store, or refused there with its reason): forgotten. Later (the store
// cannot take files now, the ledger away): it stays where it was dropped, and so do the files after
// it; the folder is offered again after retry_s, not on every turn of the main loop.
#include <chrono>
#include <functional>
#include <memory>

#include "daemon/station/station_store.hpp"
#include "daemon/watch/hot_folder.hpp"

namespace lastcut::daemon {

class FolderIntake {
 public:
  using Clock = std::chrono::steady_clock;
  using Take = std::function<StationStore::Intake(const ReadyScan&)>;

  FolderIntake(std::unique_ptr<HotFolder> folder, Take take, double retry_s = 2.0)
      : folder_(std::move(folder)), take_(std::move(take)), retry_s_(retry_s) {}

  HotFolder& folder() { return *folder_; }
  const HotFolder& folder() const { return *folder_; }
  // Offers each ready file to the store, unless the store said Later less than retry_s ago.
  void take_ready(Clock::time_point now);

 private:
  std::unique_ptr<HotFolder> folder_;
  Take take_;
  double retry_s_;
  Clock::time_point next_{};  // while the store cannot take files: when to offer them again
};

}  // namespace lastcut::daemon
