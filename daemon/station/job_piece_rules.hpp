#pragma once
// What a job's pieces (a style's, or a pattern set's) are cut from and the leather rules their
// material gives them where the style does not: the job's material is the sidecar's, else
// jobs.default_material; its grain_tolerance_deg (0 = free) and min_quality (docs/hides.md, Grades).
// One job is cut from one material: a piece whose material names another configured material holds
// the job with one line.
#include <string>
#include <utility>
#include <vector>

#include "daemon/config/daemon_config.hpp"
#include "daemon/job/job_ticket.hpp"
#include "engine/nest/pattern_items.hpp"

namespace lastcut::daemon {

struct JobMaterial {
  std::string name;  // key into DaemonConfig::materials ("" when none is configured)
  PieceRules rules;  // the material's own rules for a piece that brings none
};

JobMaterial job_material(const JobTicket& ticket, const DaemonConfig& settings);

// "" when no piece names a configured material other than the job's; else the hold reason, e.g.
// "pieces \"lining\" are of material lining-pig, the job is cut from calf-hide: one job is cut from one
// material (give those pieces a file of their own, or name one material in the sidecar)".
// piece_materials: (piece name, its material or category) each.
std::string other_material_hold(const std::vector<std::pair<std::string, std::string>>& piece_materials,
                                const JobMaterial& material, const DaemonConfig& settings);

}  // namespace lastcut::daemon
