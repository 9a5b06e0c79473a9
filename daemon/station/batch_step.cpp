// A batch of jobs -> one strip layout on the material (nest(): the material's width is the strip
// height) -> cut file for the cutter's machine profile (make_cut_file) and an SVG preview. A job
// whose mold cannot be placed (wider than the material) is taken out and the rest nested again, so
// a bad job never spoils a batch.
#include <set>

#include "daemon/station/engine_steps.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/nest/hide_batch.hpp"
#include "daemon/station/cut_outputs.hpp"
#include "engine/toolpath/cut_file.hpp"
#include "engine/toolpath/cut_job.hpp"

namespace lastcut::daemon {
namespace {

// The pieces of one job (its items of this material). Throws EngineError.
PieceGroup job_pieces(const BatchJobInput& job) {
  return {job.job_id, "", 0,
          read_part_items(job.items_file, job.copies, job.items_file.filename().string() + " of job " + job.job_id).items};
}

// What the program carries, named in the cut file itself so the machine's own log shows it.
std::vector<std::string> program_notes(const std::string& batch_id, const std::set<std::string>& job_ids) {
  std::vector<std::string> notes = {"lastcut batch " + batch_id};
  for (const std::string& id : job_ids) notes.push_back("lastcut job " + id);
  return notes;
}

}  // namespace

Result<BatchMade> build_batch(const std::vector<BatchJobInput>& jobs, const MaterialConfig& material,
                              const CutterSection& cutter, const std::filesystem::path& machines_dir,
                              double nest_time_s, const std::filesystem::path& batch_dir) {
  BatchMade outcome;
  try {
    std::vector<std::filesystem::path> search = {machines_dir};
    for (const auto& dir : standard_machine_profile_dirs()) search.push_back(dir);
    const MachineProfile profile = load_machine_profile(cutter.machine, search);

    std::set<std::string> active;
    for (const auto& job : jobs) active.insert(job.job_id);
    BatchSpec spec;
    spec.rotation_step_deg = material.rotation_step_deg;
    spec.gap_mm = material.spacing_mm;
    spec.margin_mm = material.spacing_mm;
    for (;;) {
      std::vector<PieceGroup> groups;
      for (const auto& job : jobs) {
        if (!active.count(job.job_id)) continue;
        try {
          groups.push_back(job_pieces(job));
        } catch (const EngineError& error) {
          outcome.rejected[job.job_id] = error.what();
          active.erase(job.job_id);
        }
      }
      if (groups.empty()) return outcome;
      const BatchInstance batch = strip_batch(groups, material.width_mm, spec, batch_dir.filename().string());
      const NestInstance& instance = batch.instance;
      std::map<int, std::string> owner;  // item id -> job id
      for (size_t i = 0; i < instance.items.size(); ++i) owner[instance.items[i].id] = groups[batch.group_of_item[i]].owner;
      NestOptions options;
      options.time_limit_s = nest_time_s;
      const Layout layout = nest_batch(batch, options);
      bool removed = false;
      for (const Unplaced& missing : layout.unplaced) {
        const std::string& job_id = owner[missing.item];
        if (!active.count(job_id)) continue;
        outcome.rejected[job_id] = "a mold does not fit on the material (" + missing.reason + ")";
        active.erase(job_id);
        removed = true;
      }
      if (removed) continue;  // nest the others again without it
      if (layout.strip_length && *layout.strip_length > material.length_mm) {
        outcome.measures["warning"] = "the layout is longer than the material";
      }
      if (Status written = write_file_durably(batch_dir / kLayoutFile, layout_to_json(layout, instance).dump(1));
          !written) {
        return written;
      }
      CutFileRequest request;
      request.notes = program_notes(batch_dir.filename().string(), active);
      const CutFile cut = make_cut_file(layout, instance, profile, request);
      const auto cut_file = write_cut_outputs(batch_dir, cut);
      if (!cut_file) return cut_file.status();
      outcome.cut_file = *cut_file;
      outcome.utilisation = layout.utilisation;
      outcome.piece_count = static_cast<int>(layout.placements.size());
      outcome.measures["strip_length_mm"] = layout.strip_length.value_or(0.0);
      outcome.measures["cut_length_mm"] = cut.stats.cut_length_mm;
      outcome.measures["travel_length_mm"] = cut.stats.travel_length_mm;
      outcome.measures["machine"] = profile.name;
      return outcome;
    }
  } catch (const EngineError& error) {
    return Status::failure(error.what());
  } catch (const std::exception& error) {
    return Status::failure(unexpected_failure_reason(error));
  }
}

}  // namespace lastcut::daemon
