#include "daemon/job/status_observer.hpp"

namespace lastcut::daemon {

nlohmann::json to_json(const NestingStatus& status) {
  return {{"material", status.material},
          {"hide", status.hide},
          {"batch", status.batch},
          {"cutter", status.cutter},
          {"pieces_placed", status.pieces_placed},
          {"pieces_waiting", status.pieces_waiting},
          {"jobs_placed", status.jobs_placed},
          {"jobs_waiting", status.jobs_waiting},
          {"utilisation", status.utilisation}};
}

}  // namespace lastcut::daemon
