// A job's material and its leather rules; see job_piece_rules.hpp.
#include "daemon/station/job_piece_rules.hpp"

#include <map>

namespace lastcut::daemon {

JobMaterial job_material(const JobTicket& ticket, const DaemonConfig& settings) {
  JobMaterial material;
  material.name = ticket.material.empty() ? settings.jobs.default_material : ticket.material;
  if (const auto found = settings.materials.find(material.name); found != settings.materials.end()) {
    if (found->second.grain_tolerance_deg > 0) material.rules.grain_tolerance_deg = found->second.grain_tolerance_deg;
    material.rules.min_quality = found->second.min_quality;
  }
  return material;
}

std::string other_material_hold(const std::vector<std::pair<std::string, std::string>>& piece_materials,
                                const JobMaterial& material, const DaemonConfig& settings) {
  std::map<std::string, std::string> pieces_of;  // other configured material -> its pieces, quoted
  for (const auto& [piece, piece_material] : piece_materials) {
    if (piece_material == material.name || !settings.materials.count(piece_material)) continue;
    std::string& names = pieces_of[piece_material];
    names += (names.empty() ? "\"" : ", \"") + piece + "\"";
  }
  if (pieces_of.empty()) return "";
  const auto& [other, names] = *pieces_of.begin();
  return "pieces " + names + " are of material " + other + ", the job is cut from " + material.name +
         ": one job is cut from one material (give those pieces a file of their own, or name one material in the sidecar)";
}

}  // namespace lastcut::daemon
