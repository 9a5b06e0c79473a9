#include "daemon/station/ticket_targets.hpp"

#include <set>

#include "daemon/station/engine_steps.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/pattern/aama_dxf.hpp"

namespace lastcut::daemon {

namespace {

// The one configured material the pieces of a pattern set name in their Category; "" when they name
// none or several, or the file cannot be read (computing the job says why).
std::string pattern_set_material(const std::filesystem::path& input, const DaemonConfig& config) {
  if (input.empty() || !is_pattern_set(input)) return "";
  std::set<std::string> named;
  try {
    for (const PatternPiece& piece : read_aama_dxf(input))
      if (config.materials.count(piece.category)) named.insert(piece.category);
  } catch (const EngineError&) {
    return "";  // refused when the job is computed, with the reader's line in the job's report
  }
  return named.size() == 1 ? *named.begin() : "";
}

}  // namespace

std::string settle_ticket_targets(JobTicket& ticket, const DaemonConfig& config, const std::filesystem::path& input) {
  if (ticket.material.empty()) ticket.material = pattern_set_material(input, config);
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
