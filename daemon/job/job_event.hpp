#pragma once
// JobEvent: one change of a job as its observers see it (MQTT, `lastcut status`, an operator's
// page), the same whichever store keeps the job: the spool of one station (made from its
// state.json) or the shop's PostgreSQL ledger (made from the ledger's rows). Observers never see a
// store's own record, so a field one store lacks cannot be faked by the other.
#include <string>

#include "daemon/job/job_state.hpp"
#include "daemon/job/stages.hpp"

namespace lastcut::daemon {

struct JobEvent {
  std::string job_id;
  std::string scan_name;  // the file name as dropped
  std::string order;      // the ticket's order, "" when none
  std::string material;
  std::string cutter;
  std::string batch_id;   // "" while the job is in no batch
  JobStage stage = JobStage::Claimed;
  std::string note;       // what happened, one line ("computing molds, attempt 2"); may be ""
  std::string reason;     // why failed, held, skipped or waiting; "" otherwise
  std::string at;         // ISO 8601 UTC of the change
};

// A spool job's event: the last step of its history gives the note and the time.
JobEvent job_event_of(const JobState& state);

}  // namespace lastcut::daemon
