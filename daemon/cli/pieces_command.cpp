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
#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "daemon/cli/cli_support.hpp"
#include "daemon/cli/commands.hpp"
#include "daemon/config/style_folder.hpp"
#include "daemon/cli/style_reference.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "engine/mold/mold_svg.hpp"
#include "engine/pattern/aama_dxf.hpp"
#include "engine/style/piece_pattern.hpp"
#include "engine/style/style_pieces.hpp"

namespace lastcut::cli {
namespace {

namespace fs = std::filesystem;

struct PiecesArguments {
  std::string style_dir, scan, out_dir, side = "right", size;
};

// A file name for a piece: letters, digits and '-' kept, anything else '-'.
std::string file_stem(const std::string& piece) {
  std::string stem;
  for (const char c : piece) stem += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return stem;
}

nlohmann::json point_json(const Point2& p) { return nlohmann::json::array({p.x(), p.y()}); }

double net_length_mm(const PieceMoldEdge& edge) {
  double length_mm = 0;
  for (std::size_t i = 1; i < edge.net_points.size(); ++i) length_mm += (edge.net_points[i] - edge.net_points[i - 1]).norm();
  return length_mm;
}

nlohmann::json piece_json(const StyleDefinition& style, const StylePieceResult& piece) {
  std::vector<std::string> line_names;
  for (const StyleLine& line : style.lines) line_names.push_back(line.name);
  nlohmann::json edges = nlohmann::json::array(), notches = nlohmann::json::array();
  for (const PieceMoldEdge& edge : piece.mold.edges)
    edges.push_back({{"on", to_string(edge.source, line_names)},
                     {"sewn", is_sewn(edge.source)},
                     {"allowance_mm", edge.allowance_mm},
                     {"length_mm", net_length_mm(edge)},
                     {"length_3d_mm", edge.length_3d_mm}});
  for (std::size_t n = 0; n < piece.notches.size(); ++n) {
    const PieceNotch& notch = piece.notches[n];
    notches.push_back({{"name", notch.name},
                       {"kind", notch.balance ? "balance" : "junction"},
                       {"on_net_mm", point_json(notch.net_point_mm)},
                       {"on_cut_line_mm", point_json(piece.mold.mold.marks[n].position_mm)}});
  }
  const DistortionMeasures& m = piece.mold.measures;
  return {{"name", piece.spec.name},
          {"material", piece.spec.material},
          {"quantity_per_shoe", piece.spec.quantity},
          {"file", file_stem(piece.spec.name) + ".dxf"},
          {"area_3d_mm2", piece.surface.area_mm2},
          {"D_angle", m.D_angle},
          {"D_area", m.D_area},
          {"flipped_triangles", m.flipped_triangles},
          {"converged", piece.mold.flatten.converged},
          {"grain_line_mm", nlohmann::json::array({point_json(piece.grain.from_mm), point_json(piece.grain.to_mm)})},
          {"edges", edges},
          {"notches", notches}};
}

nlohmann::json seam_json(const SeamReport& seam) {
  return {{"seam", seam.seam},
          {"one_side", seam.one_side},
          {"other_side", seam.other_side},
          {"one_side_mm", seam.one_side_mm},
          {"other_side_mm", seam.other_side_mm},
          {"difference_mm", seam.difference_mm()},
          {"length_3d_mm", seam.length_3d_mm}};
}

void write_outputs(const PiecesArguments& arguments, const daemon::StyleFolder& folder, const StyleResult& result) {
  const fs::path out(arguments.out_dir);
  const std::string& style = folder.style.name;
  nlohmann::json report = {{"style", style},
                           {"scan", arguments.scan},
                           {"size", arguments.size},
                           {"foot", arguments.side},
                           {"upper_area_3d_mm2", result.upper_area_mm2},
                           {"pieces_area_3d_mm2", result.pieces_area_mm2},
                           {"notes", result.notes},
                           {"pieces", nlohmann::json::array()},
                           {"seams", nlohmann::json::array()}};
  std::vector<PatternPiece> patterns;
  for (const StylePieceResult& piece : result.pieces) {
    Mold labelled = piece.mold.mold;  // the label the cutting room reads on the piece
    labelled.name = style + " " + piece.spec.name + (arguments.size.empty() ? "" : " " + arguments.size) + " " + arguments.side;
    const std::string stem = file_stem(piece.spec.name);
    write_mold_dxf(out / (stem + ".dxf"), labelled);
    write_mold_svg(out / (stem + ".svg"), labelled, piece.mold.UV, piece.surface.mesh.F, piece.mold.measures.sigma1);
    report["pieces"].push_back(piece_json(folder.style, piece));
    patterns.push_back(pattern_piece(piece, style, arguments.size, arguments.side));
  }
  for (const SeamReport& seam : result.seams) report["seams"].push_back(seam_json(seam));
  fs::create_directories(out / "aama");
  write_aama_dxf(out / "aama" / (file_stem(style) + (arguments.size.empty() ? "" : "-" + file_stem(arguments.size)) + "-" + arguments.side + ".dxf"),
                 patterns);
  if (const Status written = write_file_durably(out / "pieces.json", report.dump(2) + "\n"); !written) throw EngineError(written.error());
}

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
    const ScanResult reference = prepare_style_reference(*folder);
    const ScanResult target = segmented(arguments.scan, side_named(arguments.side));
    const StyleResult result = make_style_pieces(folder->style, reference, target);
    write_outputs(arguments, *folder, result);
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
