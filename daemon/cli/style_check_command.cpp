// `lastcut style check DIR [-o CHECK.svg]`: a style folder validated completely, before any last is cut
// with it (issue 34, point 1). The folder is read (daemon/config/style_folder.hpp: a mistake in style.toml
// or lines.obj is refused with its line, exit 2), then the whole pipeline runs on the style's own
// reference last: the style is cut from the reference onto itself (make_style_pieces(style, reference,
// reference)), so every line, seam cut, label and piece is tried exactly as drawn (refused with the
// engine's line, exit 1). On success it prints one line per piece (material, quantity, 3D area, its edges
// and their allowances) and draws every piece's region on the reference's two flattened halves
// (engine/style/style_check_svg.hpp), by default DIR/check.svg; the pieces of each further layer (the
// linings) in a picture of their own beside it, check-<layer>.svg.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "daemon/cli/cli_support.hpp"
#include "daemon/cli/commands.hpp"
#include "daemon/config/style_reference.hpp"
#include "daemon/config/style_folder.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/piece_formes.hpp"
#include "engine/style/style_check_svg.hpp"
#include "engine/style/style_pieces.hpp"
#include "engine/style/style_transfer.hpp"

namespace lastcut::cli {
namespace {

namespace fs = std::filesystem;

struct CheckArguments {
  std::string style_dir, svg;
};


const SegmentResult& half_named(const ScanResult& scan, const std::string& name) {
  for (const SegmentResult& half : scan.segments)
    if (half.name == name) return half;
  throw EngineError("the reference last has no " + name + " half");
}

// The pieces of one layer ("": the outer pieces), their labels and the lines that part them on the
// reference's halves, as the picture draws them.
StyleCheckSheet check_sheet(const StyleDefinition& style, const ScanResult& reference, const StyleResult& result,
                            const std::string& layer) {
  std::vector<StylePieceResult> pieces;
  for (const StylePieceResult& piece : result.pieces)
    if (piece.spec.layer == layer) pieces.push_back(piece);
  StyleCheckSheet sheet;
  sheet.title = "style " + style.name + (layer.empty() ? "" : ", layer " + layer + ",") + " on its reference last: " +
                std::to_string(pieces.size()) + (pieces.size() == 1 ? " piece" : " pieces");
  sheet.halves = {&half_named(reference, "medial"), &half_named(reference, "lateral")};
  sheet.pieces = piece_formes(sheet.halves, pieces);
  const StyleTransfer onto_itself(reference, reference);
  for (const StylePieceResult& piece : pieces) sheet.labels.push_back(onto_itself.transfer_point(piece.spec.label_mm));
  for (const StyleLine& line : style.lines)
    if (line_parts_layer(style, layer, line.name))
      sheet.lines.emplace_back(line.name, onto_itself.transfer_curve(line.points_mm));
  return sheet;
}

// "feather line 18, line vamp 8, top edge 5": what each edge of the piece lies on and its allowance (mm).
std::string edges_text(const StyleDefinition& style, const StylePieceResult& piece) {
  std::vector<std::string> line_names;
  for (const StyleLine& line : style.lines) line_names.push_back(line.name);
  std::string text;
  for (const PieceMoldEdge& edge : piece.mold.edges) {
    char allowance[32];
    std::snprintf(allowance, sizeof allowance, " %g", edge.allowance_mm);
    text += (text.empty() ? "" : ", ") + to_string(edge.source, line_names) + allowance;
  }
  return text;
}

int run_style_check(const CheckArguments& arguments) {
  Result<daemon::StyleFolder> folder = daemon::read_style_folder(arguments.style_dir);
  if (!folder) {
    print_error(folder.error());
    return 2;
  }
  const fs::path svg = arguments.svg.empty() ? fs::path(arguments.style_dir) / "check.svg" : fs::path(arguments.svg);
  try {
    const ScanResult reference = daemon::prepare_style_reference(*folder);
    const StyleResult result = make_style_pieces(folder->style, reference, reference);
    write_style_check_svg(svg, check_sheet(folder->style, reference, result, ""));
    std::vector<fs::path> drawn = {svg};
    for (const StyleLayer& layer : folder->style.layers) {
      drawn.push_back(fs::path(svg).replace_filename(svg.stem().string() + "-" + layer.name + svg.extension().string()));
      write_style_check_svg(drawn.back(), check_sheet(folder->style, reference, result, layer.name));
    }
    for (const StylePieceResult& piece : result.pieces)
      std::printf("%-16s %-14s x%d  %7.0f mm2  edges (mm): %s\n", piece.spec.name.c_str(), piece.spec.material.c_str(),
                  piece.spec.quantity, piece.surface.area_mm2, edges_text(folder->style, piece).c_str());
    for (const std::string& note : result.notes) std::printf("note: %s\n", note.c_str());
    std::string drawn_in;
    for (const fs::path& file : drawn) drawn_in += (drawn_in.empty() ? "" : ", ") + file.string();
    std::printf("style %s is OK: %zu pieces, the outer ones cover its reference last's upper (%.0f of %.0f mm2); drawn in %s\n",
                folder->style.name.c_str(), result.pieces.size(), result.pieces_area_mm2, result.upper_area_mm2,
                drawn_in.c_str());
    return 0;
  } catch (const std::exception& error) {  // EngineError among them: one line either way
    print_error(error.what());
  }
  return 1;
}

}  // namespace

void add_style_check_command(CLI::App& style, int& exit_code) {
  auto arguments = std::make_shared<CheckArguments>();
  auto* check = style.add_subcommand("check", "a style folder validated on its own reference last; its pieces drawn on the forme (SVG)");
  check->add_option("style", arguments->style_dir, "style folder (style.toml and its lines)")->required();
  check->add_option("-o,--out", arguments->svg, "the picture of the pieces on the reference's flattened halves (default STYLE/check.svg)");
  check->callback([arguments, &exit_code] { exit_code = run_style_check(*arguments); });
}

}  // namespace lastcut::cli
