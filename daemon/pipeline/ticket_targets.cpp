#include "daemon/pipeline/ticket_targets.hpp"

namespace lastcut::daemon {

std::string settle_ticket_targets(JobTicket& ticket, const DaemonConfig& config) {
  if (ticket.material.empty()) ticket.material = config.jobs.default_material;
  if (ticket.cutter.empty()) ticket.cutter = config.jobs.default_cutter;
  if (!config.materials.count(ticket.material))
    return "the sidecar asks for material \"" + ticket.material + "\", which is not configured";
  if (!config.cutters.count(ticket.cutter))
    return "the sidecar asks for cutter \"" + ticket.cutter + "\", which is not configured";
  return "";
}

}  // namespace lastcut::daemon
