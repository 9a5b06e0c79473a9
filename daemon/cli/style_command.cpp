// `lastcut style pieces STYLE_DIR SCAN -o OUT`: a style's pieces on a scanned last (issue 34). The
// style folder (daemon/config/style_folder.hpp) gives the lines drawn on its reference last; both lasts
// go through the scan-to-molds pipeline, the style is transferred and split into its pieces, and each
// piece is flattened with its allowances: OUT/PIECE.dxf (cut line, net line), OUT/PIECE.svg (with its
// stretch) and OUT/pieces.json (material, quantity, areas, distortion and each edge's allowance).
#include <nlohmann/json.hpp>

#include <cctype>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "daemon/cli/commands.hpp"
#include "daemon/config/style_folder.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "engine/mold/mold_svg.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/style_pieces.hpp"

namespace lastcut::cli {
namespace {

namespace fs = std::filesystem;

struct StyleArguments {
  std::string style_dir, scan, out_dir, side = "right";
};

void print_style_error(std::string reason) {
  for (char& c : reason)
    if (c == '\n' || c == '\r') c = ' ';
  std::fprintf(stderr, "lastcut: error: %s\n", reason.c_str());
}

ScanResult segmented(const fs::path& scan, FootSide side) {
  ScanOptions options;
  options.side = side;
  return scan_to_molds(scan, options);
}

// A file name for a piece: letters, digits and '-' kept, anything else '-'.
std::string file_stem(const std::string& piece) {
  std::string stem;
  for (const char c : piece) stem += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return stem;
}

nlohmann::json piece_json(const StyleDefinition& style, const StylePieceResult& piece) {
  std::vector<std::string> line_names;
  for (const StyleLine& line : style.lines) line_names.push_back(line.name);
  nlohmann::json edges = nlohmann::json::array();
  for (const PieceMoldEdge& edge : piece.mold.edges) {
    double length_mm = 0;
    for (std::size_t i = 1; i < edge.net_points.size(); ++i) length_mm += (edge.net_points[i] - edge.net_points[i - 1]).norm();
    edges.push_back({{"on", to_string(edge.source, line_names)},
                     {"allowance_mm", edge.allowance_mm},
                     {"length_mm", length_mm},
                     {"length_3d_mm", edge.length_3d_mm}});
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
          {"edges", edges}};
}

int run_style_pieces(const StyleArguments& arguments) {
  if (arguments.side != "left" && arguments.side != "right") {
    print_style_error("--side must be left or right, not " + arguments.side);
    return 2;
  }
  const Result<daemon::StyleFolder> folder = daemon::read_style_folder(arguments.style_dir);
  if (!folder) {
    print_style_error(folder.error());
    return 2;
  }
  try {
    fs::create_directories(arguments.out_dir);
    fs::path reference_scan = folder->reference_scan;
    if (folder->generated_reference) {  // a generated reference is made where the output goes, then removed
      reference_scan = fs::path(arguments.out_dir) / ".style-reference.stl";
      write_stl_binary(reference_scan, generate_last(*folder->generated_reference).mesh);
    }
    const ScanResult reference = segmented(reference_scan, folder->reference_side);
    if (folder->generated_reference) fs::remove(reference_scan);
    const ScanResult target = segmented(arguments.scan, arguments.side == "left" ? FootSide::Left : FootSide::Right);
    const StyleResult result = make_style_pieces(folder->style, reference, target);
    nlohmann::json report = {{"style", folder->style.name},
                             {"scan", arguments.scan},
                             {"upper_area_3d_mm2", result.upper_area_mm2},
                             {"pieces_area_3d_mm2", result.pieces_area_mm2},
                             {"notes", result.notes},
                             {"pieces", nlohmann::json::array()}};
    for (const StylePieceResult& piece : result.pieces) {
      const std::string stem = file_stem(piece.spec.name);
      write_mold_dxf(fs::path(arguments.out_dir) / (stem + ".dxf"), piece.mold.mold);
      write_mold_svg(fs::path(arguments.out_dir) / (stem + ".svg"), piece.mold.mold, piece.mold.UV, piece.surface.mesh.F,
                     piece.mold.measures.sigma1);
      report["pieces"].push_back(piece_json(folder->style, piece));
      std::printf("%-16s %-14s x%d  %7.0f mm2  D_area %.4f  edges:", piece.spec.name.c_str(), piece.spec.material.c_str(),
                  piece.spec.quantity, piece.surface.area_mm2, piece.mold.measures.D_area);
      for (const PieceMoldEdge& edge : piece.mold.edges) std::printf(" %.0f", edge.allowance_mm);
      std::printf(" mm\n");
    }
    for (const std::string& note : result.notes) std::printf("note: %s\n", note.c_str());
    if (const Status written = write_file_durably(fs::path(arguments.out_dir) / "pieces.json", report.dump(2) + "\n"); !written) {
      print_style_error(written.error());
      return 1;
    }
    std::printf("%zu pieces of style %s in %s (upper %.0f mm2, pieces %.0f mm2)\n", result.pieces.size(),
                folder->style.name.c_str(), arguments.out_dir.c_str(), result.upper_area_mm2, result.pieces_area_mm2);
    return 0;
  } catch (const EngineError& error) {
    print_style_error(error.what());
  } catch (const std::exception& error) {
    print_style_error(error.what());
  }
  return 1;
}

}  // namespace

void add_style_command(CLI::App& app, int& exit_code) {
  auto* style = app.add_subcommand("style", "styles: upper pieces drawn once on a reference last, cut from every scanned last");
  style->require_subcommand(1);
  auto arguments = std::make_shared<StyleArguments>();
  auto* pieces = style->add_subcommand("pieces", "a style's pieces on a scanned last: one DXF and SVG per piece, pieces.json");
  pieces->add_option("style", arguments->style_dir, "style folder (style.toml and its lines)")->required();
  pieces->add_option("scan", arguments->scan, "scan of the last to cut the pieces for")->required();
  pieces->add_option("-o,--out", arguments->out_dir, "output folder (created if missing)")->required();
  pieces->add_option("--side", arguments->side, "the foot the scanned last is for (left or right)")->capture_default_str();
  pieces->callback([arguments, &exit_code] { exit_code = run_style_pieces(*arguments); });
}

}  // namespace lastcut::cli
