#pragma once
// Where a scan's ticket sends it: the sidecar's material and cutter, or the configuration's
// defaults when it names none; a hide's likewise. One rule for every intake (the single-station spool and a ledger node).
#include <filesystem>
#include <string>

#include "daemon/config/daemon_config.hpp"
#include "daemon/job/job_ticket.hpp"

namespace lastcut::daemon {

// Fills an empty ticket.material / ticket.cutter from jobs.default_material / default_cutter, then
// checks both are configured: "" when they are, else the one line naming the first that is not.
// A pattern set (`input` a .dxf) whose pieces' Category names one configured material is cut from
// that material when the sidecar names none.
std::string settle_ticket_targets(JobTicket& ticket, const DaemonConfig& config, const std::filesystem::path& input = {});

// Where a hide goes (docs/hides.md): material = the hide sidecar's, else the only hide material,
// else jobs.default_material; cutter = the sidecar's, else the material's, else jobs.default_cutter.
// Fills `material` and `cutter`; "" when the material is a configured hide material and the cutter
// is configured, else the one line saying which is not (`sidecar` names the file to mend).
std::string settle_hide_targets(const std::string& hide_id, const std::string& hide_material,
                                const std::string& hide_cutter, const std::string& sidecar, const DaemonConfig& config,
                                std::string& material, std::string& cutter);

}  // namespace lastcut::daemon
