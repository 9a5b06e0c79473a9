#include "daemon/station/folder_intake.hpp"

namespace lastcut::daemon {

void FolderIntake::take_ready(Clock::time_point now) {
  if (now < next_) return;
  for (const ReadyScan& ready : folder_->collect_ready(now)) {
    std::error_code error;
    if (!std::filesystem::exists(ready.scan, error)) {
      folder_->forget(ready.scan.filename().string());  // gone meanwhile; a new event brings it back
      continue;
    }
    if (take_(ready) == StationStore::Intake::Later) {
      next_ = now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(retry_s_));
      return;  // the rest wait too
    }
    folder_->forget(ready.scan.filename().string());
    if (!ready.sidecar.empty()) folder_->forget(ready.sidecar.filename().string());
  }
}

}  // namespace lastcut::daemon
