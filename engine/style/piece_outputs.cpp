// The files of a style's pieces on one last; see piece_outputs.hpp.
#include "engine/style/piece_outputs.hpp"

#include <cctype>

#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "engine/mold/mold_svg.hpp"
#include "engine/pattern/aama_dxf.hpp"
#include "engine/style/piece_pattern.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

nlohmann::json point_json(const Point2& p) { return nlohmann::json::array({p.x(), p.y()}); }

double net_length_mm(const PieceMoldEdge& edge) {
  double length_mm = 0;
  for (std::size_t i = 1; i < edge.net_points.size(); ++i) length_mm += (edge.net_points[i] - edge.net_points[i - 1]).norm();
  return length_mm;
}

nlohmann::json piece_json(const std::vector<std::string>& line_names, const StylePieceResult& piece) {
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
          {"thickness_mm", piece.thickness_mm},
          {"file", piece_file_stem(piece.spec.name) + ".dxf"},
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

}  // namespace

std::string piece_file_stem(const std::string& piece) {
  std::string stem;
  for (const char c : piece) stem += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return stem;
}

nlohmann::json write_piece_outputs(const StyleDefinition& style, const StyleResult& result, const PieceOutputsInfo& info,
                                   const fs::path& out_dir) {
  std::error_code error;
  fs::create_directories(out_dir / "aama", error);
  if (error) throw EngineError("cannot make " + (out_dir / "aama").string() + ": " + error.message());
  nlohmann::json report = {{"style", style.name},
                           {"scan", info.scan},
                           {"size", info.size},
                           {"foot", info.foot},
                           {"upper_area_3d_mm2", result.upper_area_mm2},
                           {"pieces_area_3d_mm2", result.pieces_area_mm2},
                           {"notes", result.notes},
                           {"pieces", nlohmann::json::array()},
                           {"seams", nlohmann::json::array()}};
  std::vector<std::string> line_names;
  for (const StyleLine& line : style.lines) line_names.push_back(line.name);
  std::vector<PatternPiece> patterns;
  for (const StylePieceResult& piece : result.pieces) {
    Mold labelled = piece.mold.mold;  // the label the cutting room reads on the piece
    labelled.name = style.name + " " + piece.spec.name + (info.size.empty() ? "" : " " + info.size) + " " + info.foot;
    const std::string stem = piece_file_stem(piece.spec.name);
    write_mold_dxf(out_dir / (stem + ".dxf"), labelled);
    write_mold_svg(out_dir / (stem + ".svg"), labelled, piece.mold.UV, piece.surface.mesh.F, piece.mold.measures.sigma1);
    report["pieces"].push_back(piece_json(line_names, piece));
    patterns.push_back(pattern_piece(piece, style.name, info.size, info.foot));
  }
  for (const SeamReport& seam : result.seams) report["seams"].push_back(seam_json(seam));
  write_aama_dxf(out_dir / "aama" / (piece_file_stem(style.name) + (info.size.empty() ? "" : "-" + piece_file_stem(info.size)) + "-" + info.foot + ".dxf"),
                 patterns);
  if (const Status written = write_file_durably(out_dir / "pieces.json", report.dump(2) + "\n"); !written) throw EngineError(written.error());
  return report;
}

}  // namespace lastcut
