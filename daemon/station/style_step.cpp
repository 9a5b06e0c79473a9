// A scan with a style -> the style's pieces on that last and the job's nest items (see
// engine_steps.hpp, compute_style_pieces).
#include "daemon/config/style_folder.hpp"
#include "daemon/config/style_reference.hpp"
#include "daemon/station/engine_steps.hpp"
#include "daemon/station/job_mold_options.hpp"
#include "daemon/station/job_piece_rules.hpp"
#include "daemon/station/piece_label_text.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/piece_outputs.hpp"
#include "engine/style/style_items.hpp"

namespace lastcut::daemon {
namespace {

// Why the style the ticket names cannot be made ready (its folder, its reference last); "" when it can.
std::string style_hold(const JobTicket& ticket, const DaemonConfig& settings, Result<StyleFolder>& folder, ScanResult& reference) {
  const std::string named = "style \"" + ticket.style + "\"";
  if (settings.paths.styles_dir.empty()) return named + ": no style folder is configured ([paths] styles)";
  std::error_code unreadable;  // a folder that cannot be looked at is as good as absent
  if (!std::filesystem::is_directory(settings.paths.styles_dir / ticket.style, unreadable))
    return named + ": no such style in " + settings.paths.styles_dir.string();
  folder = read_style_folder(settings.paths.styles_dir / ticket.style);
  if (!folder) return named + ": " + folder.error();
  try {
    reference = prepare_style_reference(*folder);
  } catch (const EngineError& error) {
    return named + ": its reference last: " + error.what();
  }
  return "";
}

}  // namespace

Result<MoldsMade> compute_style_pieces(const std::filesystem::path& scan, const std::filesystem::path& job_dir,
                                       const JobTicket& ticket, const DaemonConfig& settings) {
  return guarded_job_step(job_dir, [&]() -> Result<MoldsMade> {
    MoldsMade made;
    made.noun = "pieces";
    Result<StyleFolder> folder = Status::failure("not read");
    ScanResult reference;
    made.hold_reason = style_hold(ticket, settings, folder, reference);
    if (!made.hold_reason.empty()) return made;
    // The scanned last through the same pipeline as a mold job: a bad scan fails the job here.
    const ScanResult target = scan_to_molds(scan, job_scan_options(ticket, job_mold_options(ticket, settings.jobs),
                                                                   settings.jobs.max_hole_across_mm, settings.quality));
    if (!target.quality.passed()) {
      made.hold_reason = target.quality.reason();
      return made;
    }
    const std::string foot = target.side ? std::string(to_string(*target.side)) : ticket.side == "left" ? "left" : "right";
    StyleResult pieces;
    try {
      pieces = make_style_pieces(folder->style, reference, target);
    } catch (const EngineError& error) {
      made.hold_reason = "style \"" + ticket.style + "\" does not fit this last: " + error.what();
      return made;
    }
    made.piece_count = static_cast<int>(pieces.pieces.size());
    made.measures = write_piece_outputs(folder->style, pieces, {scan.filename().string(), ticket.size, foot}, job_dir / kPiecesFolder);
    const JobMaterial material = job_material(ticket, settings);
    const auto material_of = [&](const std::string& named) { return piece_material(named, material, settings); };
    StyleNestSpec spec;
    spec.style = folder->style.name;
    spec.size = ticket.size;
    spec.foot = foot;
    spec.shoes = ticket.quantity;
    spec.other_foot = ticket.side == "pair";
    spec.draw_sew_lines = settings.jobs.draw_sew_lines;
    spec.material_rules = [&](const std::string& named) { return material_named(material_of(named), settings).rules; };
    spec.label = [&](const PatternPiece& piece, bool twin) {
      return piece_label_text({ticket.order, scan.filename().string(), ticket.size, twin ? opposite_foot(foot) : foot, piece.name});
    };
    std::vector<std::string> item_materials;  // items_from_style: each piece, then its twin
    for (const StylePieceResult& piece : pieces.pieces)
      item_materials.insert(item_materials.end(), spec.other_foot ? 2 : 1, material_of(piece.spec.material));
    return save_job_items_by_material(job_dir, items_from_style(pieces, spec), item_materials, ticket, settings, made,
                                      "pieces");
  }, "the scan is too large for this machine's memory");
}

}  // namespace lastcut::daemon
