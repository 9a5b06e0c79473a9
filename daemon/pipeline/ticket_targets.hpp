#pragma once
// Where a scan's ticket sends it: the sidecar's material and cutter, or the configuration's
// defaults when it names none. One rule for every intake (the single-station spool and a ledger node).
#include <string>

#include "daemon/config/daemon_config.hpp"
#include "daemon/spool/job_ticket.hpp"

namespace lastcut::daemon {

// Fills an empty ticket.material / ticket.cutter from jobs.default_material / default_cutter, then
// checks both are configured: "" when they are, else the one line naming the first that is not.
std::string settle_ticket_targets(JobTicket& ticket, const DaemonConfig& config);

}  // namespace lastcut::daemon
