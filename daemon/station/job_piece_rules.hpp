#pragma once
// What a job's pieces (a style's, or a pattern set's) are cut from and the leather rules their
// material gives them where the style does not. The job's material is the sidecar's, else
// jobs.default_material. A piece that names a configured material (a style piece's `material`, a
// pattern piece's Category) is cut from that one, every other piece from the job's: a job whose
// pieces name several materials is cut in parts, one per material (daemon/job/job_parts.hpp).
// A material's rules: its grain_tolerance_deg (0 = free) and min_quality (docs/hides.md, Grades).
#include <string>
#include <vector>

#include "daemon/config/daemon_config.hpp"
#include "daemon/job/job_parts.hpp"
#include "daemon/job/job_ticket.hpp"
#include "engine/nest/pattern_items.hpp"

namespace lastcut::daemon {

struct JobMaterial {
  std::string name;  // key into DaemonConfig::materials ("" when none is configured)
  PieceRules rules;  // the material's own rules for a piece that brings none
};

JobMaterial job_material(const JobTicket& ticket, const DaemonConfig& settings);
// The material `name` and its rules (none when it is not configured).
JobMaterial material_named(const std::string& name, const DaemonConfig& settings);

// The material a piece is cut from: the one it names when that is configured, else the job's.
std::string piece_material(const std::string& named, const JobMaterial& job, const DaemonConfig& settings);

// The parts of a job whose items (item_materials[i]: piece_material of item i) are of several
// materials, in cutting order: materials cut from a roll or sheet (kind strip) before hide materials,
// each group in name order. A part's cutter: the ticket's for the job's own material, else the
// material's `cutter`, else jobs.default_cutter. Pieces: the demands of its items. One material: empty.
std::vector<JobPart> job_parts(const std::vector<std::string>& item_materials, const std::vector<int>& item_demands,
                               const JobTicket& ticket, const DaemonConfig& settings);

}  // namespace lastcut::daemon
