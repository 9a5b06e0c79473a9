// A batch of jobs -> one strip layout on the material (engine/nest, strip packing: the
// material's width is the strip height) -> cut program for the cutter's machine profile
// (engine/toolpath) -> cut file and SVG preview. A job whose mold cannot be placed (wider than
// the material) is taken out and the rest nested again, so a bad job never spoils a batch.
#include <fstream>
#include <set>

#include "daemon/pipeline/engine_steps.hpp"
#include "daemon/pipeline/piece_label_text.hpp"
#include "daemon/spool/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/nest/strip_nester.hpp"
#include "engine/toolpath/cut_file.hpp"
#include "engine/toolpath/layout_pieces.hpp"
#include "engine/toolpath/plan_cut_program.hpp"
#include "engine/toolpath/svg_writer.hpp"

namespace lastcut::daemon {
namespace {

Point2 read_point(const nlohmann::json& json) { return Point2(json.at(0).get<double>(), json.at(1).get<double>()); }

Polygon2 mirrored(const Polygon2& polygon) {
  Polygon2 result;
  for (auto it = polygon.points.rbegin(); it != polygon.points.rend(); ++it) result.points.emplace_back(-it->x(), it->y());
  return result;
}

// Items of one job from its pieces.json; item ids start at next_id. Throws EngineError.
std::vector<NestItem> job_items(const BatchJobInput& job, const MaterialConfig& material, int& next_id) {
  std::ifstream in(job.job_dir / kPiecesFile);
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  if (!in || json.is_discarded() || !json.contains("pieces")) throw EngineError("the molds file pieces.json is unreadable");
  std::vector<double> rotations;
  for (int angle = 0; angle < 360; angle += material.rotation_step_deg) rotations.push_back(angle);
  // The foot is the scan's (the molds are its geometry); the sidecar's only when the scan's is unknown.
  std::string scan_foot = json.value("side", "");
  if (scan_foot.empty() && (job.ticket.side == "left" || job.ticket.side == "right")) scan_foot = job.ticket.side;
  const bool pair = job.ticket.side == "pair";
  std::vector<NestItem> items;
  for (const auto& piece : json.at("pieces")) {
    for (int mirror = 0; mirror < (pair ? 2 : 1); ++mirror) {
      NestItem item;
      item.id = next_id++;
      for (const auto& point : piece.at("outline")) item.shape.points.push_back(read_point(point));
      for (const auto& mark : piece.at("marks")) {
        item.marks.push_back({mark.at("name").get<std::string>(), read_point(mark.at("from")), read_point(mark.at("to"))});
      }
      if (mirror) {
        item.shape = mirrored(item.shape);
        for (ItemMark& mark : item.marks) {
          mark.from_mm.x() = -mark.from_mm.x();
          mark.to_mm.x() = -mark.to_mm.x();
        }
      }
      item.demand = job.ticket.quantity;
      item.allowed_rotations_deg = rotations;
      // The mirrored copy of a pair is the same half of the other foot.
      item.label = piece_label_text({job.ticket.order, job.scan_name, job.ticket.size,
                                     mirror ? opposite_foot(scan_foot) : scan_foot, piece.at("name").get<std::string>()});
      items.push_back(std::move(item));
    }
  }
  return items;
}

std::string cut_file_name(CutFileFormat format) {
  switch (format) {
    case CutFileFormat::Hpgl: return "cut.plt";
    case CutFileFormat::Gcode: return "cut.nc";
    case CutFileFormat::Dxf: return "cut.dxf";
    case CutFileFormat::Svg: return "cut.svg";
  }
  return "cut.txt";
}

}  // namespace

BatchOutcome build_batch(const std::vector<BatchJobInput>& jobs, const MaterialConfig& material,
                         const CutterSection& cutter, const std::filesystem::path& machines_dir,
                         double nest_time_s, const std::filesystem::path& batch_dir) {
  BatchOutcome outcome;
  try {
    std::vector<std::filesystem::path> search = {machines_dir};
    for (const auto& dir : standard_machine_profile_dirs()) search.push_back(dir);
    const MachineProfile profile = load_machine_profile(cutter.machine, search);

    std::set<std::string> active;
    for (const auto& job : jobs) active.insert(job.job_id);
    for (;;) {
      NestInstance instance;
      instance.name = batch_dir.filename().string();
      instance.strip_height = material.width_mm;
      instance.gap_mm = material.spacing_mm;
      instance.margin_mm = material.spacing_mm;
      std::map<int, std::string> owner;  // item id -> job id
      int next_id = 0;
      for (const auto& job : jobs) {
        if (!active.count(job.job_id)) continue;
        try {
          for (NestItem& item : job_items(job, material, next_id)) {
            owner[item.id] = job.job_id;
            instance.items.push_back(std::move(item));
          }
        } catch (const std::exception& error) {
          outcome.rejected[job.job_id] = error.what();
          active.erase(job.job_id);
        }
      }
      if (instance.items.empty()) return outcome;
      NestOptions options;
      options.time_limit_s = nest_time_s;
      Layout layout = nest_strip(instance, options);
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
      if (std::string error = write_file_durably(batch_dir / kLayoutFile, layout_to_json(layout, instance).dump(1));
          !error.empty()) {
        outcome.error = error;
        return outcome;
      }
      const CutProgram program = plan_cut_program(placed_pieces(layout, instance, SheetRef{}), profile);
      outcome.cut_file = cut_file_name(profile.native_format);
      if (std::string error = write_file_durably(batch_dir / outcome.cut_file,
                                                 write_cut_file(program, profile, profile.native_format));
          !error.empty()) {
        outcome.error = error;
        return outcome;
      }
      if (std::string error = write_file_durably(batch_dir / kPreviewFile, write_svg(program)); !error.empty()) {
        outcome.error = error;
        return outcome;
      }
      const CutStats stats = measure_program(program);
      outcome.utilisation = layout.utilisation;
      outcome.piece_count = static_cast<int>(layout.placements.size());
      outcome.measures["strip_length_mm"] = layout.strip_length.value_or(0.0);
      outcome.measures["cut_length_mm"] = stats.cut_length_mm;
      outcome.measures["travel_length_mm"] = stats.travel_length_mm;
      outcome.measures["machine"] = profile.name;
      return outcome;
    }
  } catch (const EngineError& error) {
    outcome.error = error.what();
  }
  return outcome;
}

}  // namespace lastcut::daemon
