// `lastcut pieces SCAN --style DIR -o OUT [--size LABEL] [--side left|right]` (also `lastcut style pieces
// DIR SCAN -o OUT`): a style's pieces on a scanned last (issue 34). The style folder
// (daemon/config/style_folder.hpp) gives the lines drawn on its reference last; both lasts go through
// the scan-to-molds pipeline, the style is transferred and split into its pieces, and each piece is
// flattened with its sewn edges held, grown by its allowances and given its notches and grain line:
//   OUT/PIECE.dxf        cut line, notches, net line, label (the mold DXF: `lastcut nest OUT` reads them)
//   OUT/PIECE.svg        the piece with its stretch
//   OUT/aama/STYLE-SIZE-FOOT.dxf   every piece as DXF-AAMA (engine/pattern), for pattern CAD
//   OUT/pieces.json      per piece: material, quantity, areas, distortion, edges, notches, grain line;
//                        per seam: its length on the pieces of both sides
// The files are written by write_piece_outputs (engine/style/piece_outputs.hpp), as the daemon's style jobs write them.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "daemon/cli/cli_support.hpp"
#include "daemon/cli/commands.hpp"
#include "daemon/config/style_folder.hpp"
#include "daemon/config/style_reference.hpp"
#include "engine/style/piece_outputs.hpp"
#include "engine/style/style_pieces.hpp"

namespace lastcut::cli {
namespace {

namespace fs = std::filesystem;

struct PiecesArguments {
  std::string style_dir, scan, out_dir, side = "right", size;
};

void print_summary(const PiecesArguments& arguments, const daemon::StyleFolder& folder, const StyleResult& result) {
  for (const StylePieceResult& piece : result.pieces) {
    std::printf("%-16s %-14s x%d  %7.0f mm2  D_area %.4f  %2zu notches  edges:", piece.spec.name.c_str(), piece.spec.material.c_str(),
                piece.spec.quantity, piece.surface.area_mm2, piece.mold.measures.D_area, piece.notches.size());
    for (const PieceMoldEdge& edge : piece.mold.edges) std::printf(" %.0f", edge.allowance_mm);
    std::printf(" mm\n");
  }
  for (const SeamReport& seam : result.seams)
    std::printf("seam %-14s %7.2f mm against %7.2f mm (%+.2f)\n", seam.seam.c_str(), seam.one_side_mm, seam.other_side_mm, seam.difference_mm());
  for (const std::string& note : result.notes) std::printf("note: %s\n", note.c_str());
  std::printf("%zu pieces of style %s in %s (upper %.0f mm2, pieces %.0f mm2)\n", result.pieces.size(), folder.style.name.c_str(),
              arguments.out_dir.c_str(), result.upper_area_mm2, result.pieces_area_mm2);
}

int run_pieces(const PiecesArguments& arguments) {
  if (arguments.side != "left" && arguments.side != "right") {
    print_error("--side must be left or right, not " + arguments.side);
    return 2;
  }
  Result<daemon::StyleFolder> folder = daemon::read_style_folder(arguments.style_dir);
  if (!folder) {
    print_error(folder.error());
    return 2;
  }
  try {
    fs::create_directories(arguments.out_dir);
    const ScanResult reference = daemon::prepare_style_reference(*folder);
    const ScanResult target = segmented(arguments.scan, side_named(arguments.side));
    const StyleResult result = make_style_pieces(folder->style, reference, target);
    write_piece_outputs(folder->style, result, {arguments.scan, arguments.size, arguments.side}, arguments.out_dir);
    print_summary(arguments, *folder, result);
    return 0;
  } catch (const std::exception& error) {  // EngineError among them: one line either way
    print_error(error.what());
  }
  return 1;
}

void add_common_options(CLI::App& command, PiecesArguments& arguments) {
  command.add_option("-o,--out", arguments.out_dir, "output folder (created if missing)")->required();
  command.add_option("--side", arguments.side, "the foot the scanned last is for (left or right)")->capture_default_str();
  command.add_option("--size", arguments.size, "the size label written on the pieces (e.g. 42)");
}

}  // namespace

void add_pieces_command(CLI::App& app, int& exit_code) {
  auto arguments = std::make_shared<PiecesArguments>();
  auto* command = app.add_subcommand("pieces", "a style's pieces on a scanned last: DXF and SVG per piece, DXF-AAMA, pieces.json");
  command->add_option("scan", arguments->scan, "scan of the last to cut the pieces for")->required();
  command->add_option("--style", arguments->style_dir, "style folder (style.toml and its lines or forme)")->required();
  add_common_options(*command, *arguments);
  command->callback([arguments, &exit_code] { exit_code = run_pieces(*arguments); });
}

void add_style_pieces_command(CLI::App& style, int& exit_code) {
  auto arguments = std::make_shared<PiecesArguments>();
  auto* command = style.add_subcommand("pieces", "a style's pieces on a scanned last (the same as `lastcut pieces SCAN --style STYLE`)");
  command->add_option("style", arguments->style_dir, "style folder (style.toml and its lines or forme)")->required();
  command->add_option("scan", arguments->scan, "scan of the last to cut the pieces for")->required();
  add_common_options(*command, *arguments);
  command->callback([arguments, &exit_code] { exit_code = run_pieces(*arguments); });
}

}  // namespace lastcut::cli
