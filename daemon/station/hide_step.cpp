// A hide on a cutter's table -> the waiting pieces nested on it -> cut file, preview, report and
// offcut (see hide_step.hpp).
#include "daemon/station/hide_step.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "daemon/station/engine_steps.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_batch.hpp"
#include "engine/nest/hide_file.hpp"
#include "engine/nest/hide_mirror_pairs.hpp"
#include "engine/nest/hide_offcut.hpp"
#include "engine/nest/nest_json.hpp"
#include "daemon/station/cut_outputs.hpp"
#include "engine/toolpath/cut_file.hpp"
#include "engine/toolpath/cut_job.hpp"

namespace lastcut::daemon {
namespace {

// Where a group's items came from in its job's items file.
struct SplitShape {
  std::vector<int> file_index;  // per item of the group
  int file_items = 0;           // items in the file
};

// The copies of group g's items that the layout placed (placed_copies: batch item id -> copies on the
// hide) and left out, per item of its job's items file.
PartSplit split_of(const BatchInstance& batch, const std::map<int, int>& placed_copies, int g, const SplitShape& shape) {
  PartSplit split;
  split.placed.assign(static_cast<std::size_t>(shape.file_items), 0);
  split.rest = split.placed;
  std::size_t k = 0;  // the group's items are consecutive in the batch, in the group's order
  for (std::size_t i = 0; i < batch.instance.items.size(); ++i) {
    if (batch.group_of_item[i] != g) continue;
    const NestItem& item = batch.instance.items[i];
    const auto file = static_cast<std::size_t>(shape.file_index.at(k++));
    const auto copies = placed_copies.find(item.id);
    const int on_hide = copies == placed_copies.end() ? 0 : std::min(item.demand, copies->second);
    split.placed[file] = on_hide;
    split.rest[file] = item.demand - on_hide;
  }
  return split;
}

}  // namespace

Result<HideMade> build_hide(const std::vector<HideJobInput>& jobs, const std::filesystem::path& hide_dir,
                            const std::string& hide_file, const MaterialConfig& material, const CutterSection& cutter,
                            const std::filesystem::path& machines_dir, double nest_time_s) {
  HideMade made;
  try {
    const HideFile hide = read_hide_file(hide_dir / hide_file);
    std::vector<std::filesystem::path> search = {machines_dir};
    for (const auto& dir : standard_machine_profile_dirs()) search.push_back(dir);
    const MachineProfile profile = load_machine_profile(cutter.machine, search);

    std::vector<PieceGroup> groups;
    std::vector<SplitShape> shapes;  // per group
    for (const HideJobInput& job : jobs) {
      try {
        PartItems part =
            read_part_items(job.items_file, job.copies, job.items_file.filename().string() + " of job " + job.job_id);
        shapes.push_back({std::move(part.file_index), part.file_items});
        // A job that may split joins no pair: its pieces go where they fit (hide_batch.hpp).
        groups.push_back({job.job_id, job.order, job.priority, std::move(part.items), job.may_split});
      } catch (const EngineError& error) {
        made.rejected[job.job_id] = error.what();
      }
    }
    nlohmann::json report{{"hide", hide.hide_id},
                          {"file", hide_file},
                          {"area_m2", hide.area_m2},
                          {"usable_area_m2", hide.usable_area_m2},
                          {"machine", profile.name}};
    if (hide.thickness_mm) report["thickness_mm"] = *hide.thickness_mm;
    if (groups.empty()) {
      report["pieces_placed"] = 0;
      made.report = report;
      if (Status written = write_file_durably(hide_dir / kHideReportFile, report.dump(2) + "\n"); !written) return written;
      return made;
    }
    BatchSpec spec;
    spec.rotation_step_deg = material.rotation_step_deg;
    spec.pairs = material.pairs_same_hide ? PairPolicy::SameHide : PairPolicy::Any;
    spec.side_by_side = material.pieces_side_by_side;
    spec.mirror_pairs = material.mirror_pairs;
    spec.gap_mm = material.spacing_mm;
    spec.margin_mm = material.spacing_mm;
    spec.min_quality = material.min_quality;
    spec.toe_min_quality = material.toe_min_quality;
    spec.toe_fraction = material.toe_fraction;
    if (material.grain_tolerance_deg > 0) spec.grain_tolerance_deg = material.grain_tolerance_deg;
    const BatchInstance batch = hide_batch(groups, {hide.bin}, spec, hide_dir.filename().string());
    NestOptions options;
    options.time_limit_s = nest_time_s;
    const Layout layout = nest_batch(batch, options);

    std::vector<bool> placed(groups.size(), false);
    for (int g : placed_groups(batch, layout)) placed[g] = true;
    nlohmann::json waiting = nlohmann::json::array();
    nlohmann::json split = nlohmann::json::array();
    std::map<int, int> placed_copies;  // batch item id -> copies on the hide
    for (const Placement& p : layout.placements) ++placed_copies[p.item];
    for (size_t g = 0; g < groups.size(); ++g) {
      if (placed[g]) {
        made.placed.push_back(groups[g].owner);
        continue;
      }
      if (groups[g].may_split) {
        const PartSplit parted = split_of(batch, placed_copies, static_cast<int>(g), shapes[g]);
        const int on_hide = count_copies(parted.placed), left = count_copies(parted.rest);
        if (on_hide > 0) {
          made.placed.push_back(groups[g].owner);
          made.split[groups[g].owner] = parted;
          made.pieces_waiting += left;
          split.push_back({{"job", groups[g].owner}, {"pieces_placed", on_hide}, {"pieces_waiting", left}});
          continue;
        }
      }
      std::string reason = "did not fit on hide " + hide.hide_id;
      for (const Unplaced& u : layout.unplaced)
        for (size_t i = 0; i < batch.instance.items.size(); ++i)
          if (batch.instance.items[i].id == u.item && batch.group_of_item[i] == static_cast<int>(g))
            reason = "did not fit on hide " + hide.hide_id + " (" + u.reason + ")";
      made.waiting[groups[g].owner] = reason;
      for (const NestItem& item : groups[g].items) made.pieces_waiting += item.demand;
      waiting.push_back({{"job", groups[g].owner}, {"order", groups[g].order}, {"reason", reason}});
    }
    made.piece_count = static_cast<int>(layout.placements.size());
    made.utilisation = layout.utilisation;
    report["pieces_placed"] = made.piece_count;
    report["jobs_placed"] = made.placed;
    report["jobs_waiting"] = waiting;
    if (!split.empty()) report["jobs_split"] = split;
    report["pieces_waiting"] = made.pieces_waiting;
    report["utilisation_of_usable_area"] = layout.utilisation;
    // A shoe's piece and the other foot's copy on this hide, and how many lie mirrored about the backbone.
    if (const MirroredPairs twins = count_mirrored_pairs(layout, batch.instance); twins.pairs > 0)
      report["pairs_mirrored_about_backbone"] = {{"pairs", twins.pairs}, {"mirrored", twins.mirrored}};
    if (made.placed.empty()) {
      made.report = report;
      if (Status written = write_file_durably(hide_dir / kHideReportFile, report.dump(2) + "\n"); !written) return written;
      return made;
    }
    if (Status written = write_file_durably(hide_dir / kLayoutFile, layout_to_json(layout, batch.instance).dump(1));
        !written) {
      return written;
    }
    CutFileRequest request;
    request.sheet = SheetRef{0, 0};
    request.notes = {"lastcut hide " + hide.hide_id + " batch " + hide_dir.filename().string()};
    for (const std::string& id : made.placed) request.notes.push_back("lastcut job " + id);
    const CutFile cut = make_cut_file(layout, batch.instance, profile, request);
    const auto cut_file = write_cut_outputs(hide_dir, cut);
    if (!cut_file) return cut_file.status();
    made.cut_file = *cut_file;
    const Offcut offcut = hide_offcut(layout, batch.instance, 0);
    if (Status written = write_file_durably(hide_dir / kOffcutFile, offcut_dxf(offcut)); !written) return written;
    report["offcut_file"] = kOffcutFile;
    report["offcut_area_m2"] = offcut.area_mm2 * 1e-6;
    report["cut_file"] = made.cut_file;
    report["cut_length_mm"] = cut.stats.cut_length_mm;
    made.report = report;
    if (Status written = write_file_durably(hide_dir / kHideReportFile, report.dump(2) + "\n"); !written) return written;
    return made;
  } catch (const EngineError& error) {
    return Status::failure(error.what());
  } catch (const std::exception& error) {
    return Status::failure(unexpected_failure_reason(error));
  }
}

}  // namespace lastcut::daemon
