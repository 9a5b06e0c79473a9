#include "daemon/station/ticket_targets.hpp"

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

std::string settle_hide_targets(const std::string& hide_id, const std::string& hide_material,
                                const std::string& hide_cutter, const std::string& sidecar, const DaemonConfig& config,
                                std::string& material, std::string& cutter) {
  material = hide_material;
  if (material.empty()) {
    std::vector<std::string> hide_materials;
    for (const auto& [key, section] : config.materials)
      if (section.kind == MaterialKind::Hide) hide_materials.push_back(key);
    material = hide_materials.size() == 1 ? hide_materials.front() : config.jobs.default_material;
  }
  const auto section = config.materials.find(material);
  if (section == config.materials.end() || section->second.kind != MaterialKind::Hide)
    return "hide " + hide_id + ": material \"" + material + "\" is not a configured hide material (kind = \"hide\"); name it in " + sidecar;
  cutter = !hide_cutter.empty() ? hide_cutter : !section->second.cutter.empty() ? section->second.cutter : config.jobs.default_cutter;
  if (!config.cutters.count(cutter)) return "hide " + hide_id + ": cutter \"" + cutter + "\" is not configured";
  return "";
}

}  // namespace lastcut::daemon
