// A pattern set (DXF-AAMA) -> the job's nest items (see engine_steps.hpp, compute_pattern_items).
#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <set>

#include "daemon/station/engine_steps.hpp"
#include "daemon/station/job_piece_rules.hpp"
#include "daemon/station/piece_label_text.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/nest/pattern_items.hpp"
#include "engine/pattern/aama_dxf.hpp"

namespace lastcut::daemon {
namespace {

// The foot a piece is for, from its Annotation ("left", "right", "L", "R"; "" when it says neither).
std::string foot_of(const PatternPiece& piece) {
  std::string text = piece.annotation;
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  if (text == "left" || text == "l") return "left";
  if (text == "right" || text == "r") return "right";
  return "";
}

nlohmann::json pieces_json(const std::vector<PatternPiece>& pieces) {
  nlohmann::json list = nlohmann::json::array();
  for (const PatternPiece& piece : pieces) {
    list.push_back({{"name", piece.name},
                    {"size", piece.size},
                    {"category", piece.category},
                    {"quantity", piece.quantity},
                    {"area_mm2", std::abs(signed_area(Polygon2{piece.cut_line_mm}))},
                    {"notches", piece.notches.size()},
                    {"grain_line", piece.grain_line_mm.has_value()}});
  }
  return list;
}

}  // namespace

bool is_pattern_set(const std::filesystem::path& input) {
  std::string extension = input.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return extension == ".dxf";
}

Result<MoldsMade> compute_pattern_items(const std::filesystem::path& pattern, const std::filesystem::path& job_dir,
                                        const JobTicket& ticket, const DaemonConfig& settings) {
  return guarded_job_step(job_dir, [&]() -> Result<MoldsMade> {
    // Read by name, not path: the refusal names the file the operator dropped, not the job folder it moved to.
    std::ifstream in(pattern, std::ios::binary);
    if (!in) return Status::failure("cannot read pattern file " + pattern.filename().string());
    std::ostringstream content;
    content << in.rdbuf();
    const std::vector<PatternPiece> pieces = read_aama_dxf_text(content.str(), pattern.filename().string());
    MoldsMade made;
    made.noun = "pieces";
    made.piece_count = static_cast<int>(pieces.size());
    made.measures = {{"pattern_set", pattern.filename().string()}, {"pieces", pieces_json(pieces)}};
    const JobMaterial material = job_material(ticket, settings);
    PatternNestSpec spec;
    spec.sets = ticket.quantity;
    spec.mirrored_twins = ticket.side == "pair";
    spec.draw_sew_lines = settings.jobs.draw_sew_lines;
    spec.rules = [&](const PatternPiece& piece) {
      return material_named(piece_material(piece.category, material, settings), settings).rules;
    };
    spec.label = [&](const PatternPiece& piece, bool twin) {
      std::string foot = foot_of(piece);  // the piece's own Annotation, else the sidecar's one foot
      if (foot.empty() && ticket.side != "pair") foot = ticket.side;
      const std::string size = !ticket.size.empty() ? ticket.size : piece.size;
      return piece_label_text({ticket.order, pattern.filename().string(), size, twin ? opposite_foot(foot) : foot, piece.name});
    };
    std::vector<std::string> item_materials;  // items_from_pattern: each piece, then its twin
    for (const PatternPiece& piece : pieces)
      item_materials.insert(item_materials.end(), spec.mirrored_twins ? 2 : 1, piece_material(piece.category, material, settings));
    return save_job_items_by_material(job_dir, items_from_pattern(pieces, spec), item_materials, ticket, settings, made,
                                      "pieces");
  }, "the pattern set is too large for this machine's memory");
}

}  // namespace lastcut::daemon
