// A job's materials, their leather rules and the parts of a job of several; see job_piece_rules.hpp.
#include "daemon/station/job_piece_rules.hpp"

#include <algorithm>
#include <map>

namespace lastcut::daemon {

JobMaterial material_named(const std::string& name, const DaemonConfig& settings) {
  JobMaterial material;
  material.name = name;
  if (const auto found = settings.materials.find(material.name); found != settings.materials.end()) {
    if (found->second.grain_tolerance_deg > 0) material.rules.grain_tolerance_deg = found->second.grain_tolerance_deg;
    material.rules.min_quality = found->second.min_quality;
  }
  return material;
}

JobMaterial job_material(const JobTicket& ticket, const DaemonConfig& settings) {
  return material_named(ticket.material.empty() ? settings.jobs.default_material : ticket.material, settings);
}

std::string piece_material(const std::string& named, const JobMaterial& job, const DaemonConfig& settings) {
  return settings.materials.count(named) ? named : job.name;
}

std::vector<JobPart> job_parts(const std::vector<std::string>& item_materials, const std::vector<int>& item_demands,
                               const JobTicket& ticket, const DaemonConfig& settings) {
  std::map<std::string, int> pieces_of;
  for (std::size_t i = 0; i < item_materials.size() && i < item_demands.size(); ++i)
    pieces_of[item_materials[i]] += item_demands[i];
  if (pieces_of.size() < 2) return {};
  const JobMaterial own = job_material(ticket, settings);
  std::vector<JobPart> parts;
  for (const auto& [material, pieces] : pieces_of) {
    const auto section = settings.materials.find(material);
    const std::string& configured = section != settings.materials.end() ? section->second.cutter : std::string();
    const std::string cutter = material == own.name && !ticket.cutter.empty() ? ticket.cutter
                               : !configured.empty()                         ? configured
                                                                             : settings.jobs.default_cutter;
    parts.push_back({material, cutter, pieces});
  }
  const auto on_hide = [&](const JobPart& part) {
    const auto section = settings.materials.find(part.material);
    return section != settings.materials.end() && section->second.kind == MaterialKind::Hide;
  };
  // Stable: within strips and within hides, name order stays.
  std::stable_partition(parts.begin(), parts.end(), [&](const JobPart& part) { return !on_hide(part); });
  return parts;
}

}  // namespace lastcut::daemon
