// `lastcut style pieces STYLE_DIR SCAN -o OUT`: a style's pieces on a scanned last (issue 34). The
// style folder (daemon/config/style_folder.hpp) gives the lines drawn on its reference last; both lasts
// go through the scan-to-molds pipeline, the style is transferred and split into its pieces, and each
// piece is flattened with its allowances: OUT/PIECE.dxf (cut line, net line), OUT/PIECE.svg (with its
// stretch) and OUT/pieces.json (material, quantity, areas, distortion and each edge's allowance).
//
// `lastcut style transfer REFERENCE_SCAN LINES.obj NEW_SCAN -o OUT.obj`: lines drawn on a reference last
// (OBJ polylines, engine/style/style_lines_obj.hpp) taken onto another scanned last (style_transfer.hpp),
// written as OBJ polylines in the new scan's frame under the same names, one summary line per line.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "daemon/cli/commands.hpp"
#include "daemon/config/style_folder.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "engine/mold/mold_svg.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/style_lines_obj.hpp"
#include "engine/style/style_pieces.hpp"
#include "engine/style/style_transfer.hpp"

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

ScanResult segmented(const fs::path& scan, std::optional<FootSide> side) {
  ScanOptions options;
  options.side = side;
  return scan_to_molds(scan, options);
}

// "left" or "right" as a side; anything else (an unset option) names none.
std::optional<FootSide> side_named(const std::string& side) {
  if (side == "left") return FootSide::Left;
  if (side == "right") return FootSide::Right;
  return std::nullopt;
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
    const ScanResult target = segmented(arguments.scan, side_named(arguments.side));
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
  } catch (const std::exception& error) {  // EngineError among them: one line either way
    print_style_error(error.what());
  }
  return 1;
}

struct TransferArguments {
  std::string reference_scan, lines, scan, out;
  std::string side, reference_side;  // "", left or right (as `lastcut flatten --side`)
};

// "" when value is empty, left or right, otherwise the one-line refusal (the words of `lastcut flatten`).
std::string side_problem(const std::string& option, const std::string& value) {
  return value.empty() || value == "left" || value == "right" ? "" : option + " must be left or right, not \"" + value + "\"";
}


bool on_upper_edge(const TransferredPoint& point) {
  return point.on_outline && (point.edge == EdgeKind::Feather || point.edge == EdgeKind::Top);
}

// Closer than this, two transferred points are one (a seam crossing comes once per half, at one point).
constexpr double kSamePoint_mm = 1e-6;
// Where a line leaves the upper and comes back (over the sole, across the top opening), its two crossings
// follow each other; farther apart than this (3 reference samples), they end one run and start the next,
// and no chord is drawn across the sole. A line through a corner of the upper enters and leaves within one.
constexpr double kRunGap_mm = 3.0;

// A transferred line as the runs it makes on the new last's upper, each >= 2 points. A closed line
// (first point repeated last) whose start lies on the upper has its last run go on into its first.
std::vector<std::vector<Eigen::Vector3d>> runs_on_upper(const TransferredCurve& curve, bool closed) {
  std::vector<std::vector<Eigen::Vector3d>> runs(1);
  for (std::size_t i = 0; i < curve.points.size(); ++i) {
    const Eigen::Vector3d& p = curve.points[i].position_mm;
    if (i > 0) {
      const double step_mm = (p - curve.points[i - 1].position_mm).norm();
      if (step_mm < kSamePoint_mm) continue;
      if (step_mm > kRunGap_mm && on_upper_edge(curve.points[i - 1]) && on_upper_edge(curve.points[i])) runs.emplace_back();
    }
    runs.back().push_back(p);
  }
  if (closed && runs.size() > 1 && !on_upper_edge(curve.points.front()) &&
      (runs.back().back() - runs.front().front()).norm() < kSamePoint_mm) {
    runs.back().insert(runs.back().end(), runs.front().begin() + 1, runs.front().end());
    runs.erase(runs.begin());
  }
  std::erase_if(runs, [](const auto& run) { return run.size() < 2; });
  return runs;
}

int run_style_transfer(const TransferArguments& arguments) {
  for (const std::string& problem :
       {side_problem("--side", arguments.side), side_problem("--reference-side", arguments.reference_side)}) {
    if (problem.empty()) continue;
    print_style_error(problem);
    return 2;
  }
  try {
    const std::vector<StyleLine> lines = read_style_lines_obj(arguments.lines);  // a bad file is refused before the scans are read
    const ScanResult reference = segmented(arguments.reference_scan, side_named(arguments.reference_side));
    const ScanResult target = segmented(arguments.scan, side_named(arguments.side));
    const StyleTransfer transfer(reference, target);
    std::set<std::string> names;
    for (const StyleLine& line : lines) names.insert(line.name);
    std::vector<StyleLine> out;
    std::vector<std::string> summary;
    for (const StyleLine& line : lines) {
      const TransferredCurve curve = transfer.transfer_curve(line.points_mm);
      const bool closed = (line.points_mm.back() - line.points_mm.front()).norm() < kSamePoint_mm;
      const std::vector<std::vector<Eigen::Vector3d>> runs = runs_on_upper(curve, closed);
      if (runs.empty()) throw EngineError("the line \"" + line.name + "\" does not lie on the reference last's upper");
      std::size_t written = 0;
      for (std::size_t r = 0; r < runs.size(); ++r) {
        // A line that leaves the upper and comes back is written in parts: NAME, NAME (2), ...
        const std::string name = r == 0 ? line.name : line.name + " (" + std::to_string(r + 1) + ")";
        if (r > 0 && !names.insert(name).second)
          throw EngineError("the line \"" + line.name + "\" leaves the upper and comes back: its part \"" + name +
                            "\" would take the name of another line");
        out.push_back({name, runs[r]});
        written += runs[r].size();
      }
      const auto on_edge = std::count_if(curve.points.begin(), curve.points.end(), on_upper_edge);
      char text[160];
      std::snprintf(text, sizeof text, "%5zu points written  %5d dropped (off the reference's upper)  %2td on an edge of the upper",
                    written, curve.dropped_points, on_edge);
      summary.push_back(line.name + std::string(line.name.size() < 16 ? 16 - line.name.size() : 0, ' ') + " " + text +
                        (runs.size() > 1 ? "  in " + std::to_string(runs.size()) + " parts" : ""));
    }
    write_style_lines_obj(arguments.out, out);  // the summary only once the file is there
    for (const std::string& line : summary) std::printf("%s\n", line.c_str());
    std::printf("%zu lines onto %s in %s\n", lines.size(), arguments.scan.c_str(), arguments.out.c_str());
    return 0;
  } catch (const std::exception& error) {  // EngineError among them: one line either way
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
  auto transfer_arguments = std::make_shared<TransferArguments>();
  auto* transfer = style->add_subcommand("transfer", "lines drawn on a reference last taken onto another scanned last (OBJ polylines)");
  transfer->add_option("reference", transfer_arguments->reference_scan, "scan of the reference last the lines are drawn on")->required();
  transfer->add_option("lines", transfer_arguments->lines, "the lines: OBJ polylines (v, l) in the reference scan's frame, mm")->required();
  transfer->add_option("scan", transfer_arguments->scan, "scan of the last to take the lines to")->required();
  transfer->add_option("-o,--out", transfer_arguments->out, "output OBJ: the lines on the new last, in its scan's frame")->required();
  transfer->add_option("--side", transfer_arguments->side, "the foot the new last is for (left or right): names the halves of a symmetric last");
  transfer->add_option("--reference-side", transfer_arguments->reference_side, "the foot the reference last is for (left or right)");
  transfer->callback([transfer_arguments, &exit_code] { exit_code = run_style_transfer(*transfer_arguments); });
  add_style_check_command(*style, exit_code);
}

}  // namespace lastcut::cli
