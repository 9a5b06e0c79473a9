#include "daemon/config/style_folder.hpp"

#include <algorithm>

#include <toml++/toml.h>

#include "daemon/config/table_reader.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/style/piece_thickness.hpp"

namespace lastcut::daemon {
namespace {

// Each table of an array of tables ([[piece]] ...), read by `read_one`; anything else is an error.
template <typename ReadOne>
void each_table(TableReader& root, const std::string& key, std::vector<std::string>& errors, ReadOne read_one) {
  const toml::node* found = root.node(key);
  if (!found) return;
  const toml::array* list = found->as_array();
  if (!list) {
    errors.push_back(where(key, *found) + ": must be tables [[" + key + "]]");
    return;
  }
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::table* table = (*list)[i].as_table();
    if (!table) {
      errors.push_back(where(key, (*list)[i]) + ": must be a table");
      continue;
    }
    TableReader reader(*table, key + "[" + std::to_string(i + 1) + "]", errors);
    read_one(reader);
    reader.reject_unknown();
  }
}

void read_side(TableReader& reader, const std::string& key, FootSide& side, std::vector<std::string>& errors) {
  std::string text = side == FootSide::Left ? "left" : "right";
  reader.text(key, text, true);
  if (text == "left") side = FootSide::Left;
  else if (text == "right") side = FootSide::Right;
  else errors.push_back(reader.key_path(key) + ": must be \"left\" or \"right\"");
}

// [allowances] of the style, or of one [[piece]] over the style's: lasting, folding, underlay, butted (mm).
void read_allowances(TableReader& reader, StyleAllowances& a) {
  reader.number("lasting", a.lasting_mm, 0, 60);
  reader.number("folding", a.folding_mm, 0, 60);
  reader.number("underlay", a.underlay_mm, 0, 30);
  reader.number("butted", a.butted_mm, 0, 30);
  reader.reject_unknown();
}

}  // namespace

Result<StyleFolder> read_style_folder(const std::filesystem::path& folder) {
  const std::filesystem::path file = folder / "style.toml";
  toml::table root_table;
  try {
    root_table = toml::parse_file(file.string());
  } catch (const toml::parse_error& error) {
    return Status::failure(file.string() + " (line " + std::to_string(error.source().begin.line) +
                           "): " + std::string(error.description()));
  }
  std::vector<std::string> errors;
  StyleFolder result;
  TableReader root(root_table, "", errors);
  root.text("name", result.style.name, true);
  std::string lines_file, forme_file;
  root.text("lines", lines_file);
  root.text("forme", forme_file);
  if (lines_file.empty() == forme_file.empty())
    errors.push_back("give either lines (style lines drawn on the last, OBJ) or forme (drawn on its forme, DXF)");
  root.number("thickness_mm", result.style.thickness_mm, 0, kMaxPieceThickness_mm);

  if (const toml::table* table = root.subtable("reference", true)) {
    TableReader reader(*table, "reference", errors);
    std::string scan;
    reader.text("scan", scan);
    read_side(reader, "side", result.reference_side, errors);
    int eu_size = 0, triangles = 40000;
    reader.integer("generated_eu_size", eu_size, 35, 47);
    reader.integer("generated_triangles", triangles, 2000, 1000000);
    reader.reject_unknown();
    if (scan.empty() == (eu_size == 0)) {
      errors.push_back("reference: give either scan or generated_eu_size");
    } else if (!scan.empty()) {
      result.reference_scan = resolve(folder, scan);
    } else {
      LastParams params = LastParams::for_eu_size(eu_size, result.reference_side);
      params.target_triangles = triangles;
      result.generated_reference = params;
    }
  }
  if (const toml::table* table = root.subtable("allowances", false)) {
    TableReader reader(*table, "allowances", errors);
    read_allowances(reader, result.style.allowances);
  }
  each_table(root, "line", errors, [&](TableReader& reader) {
    StyleLineRule rule;
    reader.text("name", rule.line, true);
    reader.text("under", rule.under);
    result.style.line_rules.push_back(rule);
  });
  each_table(root, "seam_cut", errors, [&](TableReader& reader) {
    StyleSeamCut cut;
    std::string seam;
    reader.text("seam", seam, true);
    if (seam == "front") cut.seam = EdgeKind::FrontSeam;
    else if (seam == "back") cut.seam = EdgeKind::BackSeam;
    else errors.push_back(reader.key_path("seam") + ": must be \"front\" or \"back\"");
    reader.text("from_line", cut.from_line);
    reader.text("layer", cut.layer);
    result.style.seam_cuts.push_back(cut);
  });
  each_table(root, "layer", errors, [&](TableReader& reader) {
    StyleLayer layer;
    reader.text("name", layer.name, true);
    reader.boolean("partial", layer.partial);
    const toml::node* lines = reader.node("lines");
    const toml::array* names = lines ? lines->as_array() : nullptr;
    if (!names || !std::all_of(names->begin(), names->end(), [](const toml::node& n) { return n.is_string(); }))
      errors.push_back(reader.key_path("lines") + ": must be a list of the style's line names, [\"vamp\"] ([] when no line parts it)");
    else
      for (const toml::node& name : *names) layer.lines.push_back(*name.value<std::string>());
    result.style.layers.push_back(layer);
  });
  each_table(root, "piece", errors, [&](TableReader& reader) {
    StylePiece piece;
    reader.text("name", piece.name, true);
    if (const toml::node* label = reader.node("label")) {
      const toml::array* xyz = label->as_array();
      if (!xyz || xyz->size() != 3 || !std::all_of(xyz->begin(), xyz->end(), [](const toml::node& n) { return n.is_number(); }))
        errors.push_back(where(reader.key_path("label"), *label) + ": must be three numbers [x, y, z] in mm");
      else
        for (int k = 0; k < 3; ++k) piece.label_mm(k) = *(*xyz)[static_cast<std::size_t>(k)].value<double>();
      if (!forme_file.empty())
        errors.push_back(reader.key_path("label") + ": a style drawn on its forme places each piece by its text on layer PIECES");
    } else if (forme_file.empty()) {
      errors.push_back(reader.key_path("label") + ": missing (required)");
    }
    reader.text("material", piece.material);
    reader.text("layer", piece.layer);
    reader.integer("quantity", piece.quantity, 1, 20);
    reader.number("grain_deg", piece.grain_deg, -180, 180);
    double grain_tolerance_deg = -1;  // absent: the material's default
    reader.number("grain_tolerance_deg", grain_tolerance_deg, 0, 90);
    if (grain_tolerance_deg >= 0) piece.grain_tolerance_deg = grain_tolerance_deg;
    int min_quality = -1;
    reader.integer("min_quality", min_quality, 0, 100);
    if (min_quality >= 0) piece.min_quality = min_quality;
    double thickness_mm = -1;  // absent: the style's
    reader.number("thickness_mm", thickness_mm, 0, kMaxPieceThickness_mm);
    if (thickness_mm >= 0) piece.thickness_mm = thickness_mm;
    if (const toml::table* table = reader.subtable("allowances", false)) {
      // The piece's own, over the style's ([allowances] is read before the pieces, wherever it stands).
      TableReader allowances(*table, reader.key_path("allowances"), errors);
      piece.allowances = result.style.allowances;
      read_allowances(allowances, *piece.allowances);
    }
    result.style.pieces.push_back(piece);
  });
  root.reject_unknown();
  // Every layer a piece or seam cut names is a [[layer]] (the outer pieces name none).
  const auto has_layer = [&](const std::string& name) {
    return name.empty() || std::any_of(result.style.layers.begin(), result.style.layers.end(),
                                       [&](const StyleLayer& layer) { return layer.name == name; });
  };
  for (const StylePiece& piece : result.style.pieces)
    if (!has_layer(piece.layer)) errors.push_back("piece \"" + piece.name + "\": layer \"" + piece.layer + "\" is not a [[layer]]");
  for (const StyleSeamCut& cut : result.style.seam_cuts)
    if (!has_layer(cut.layer)) errors.push_back("seam_cut: layer \"" + cut.layer + "\" is not a [[layer]]");
  if (result.style.pieces.empty() && forme_file.empty() && errors.empty()) errors.push_back("no [[piece]]: a style needs at least one piece");
  if (errors.empty()) {
    try {
      if (!forme_file.empty())
        result.forme = read_forme_drawing(resolve(folder, forme_file));
      else
        result.style.lines = read_style_lines_obj(resolve(folder, lines_file));
    } catch (const EngineError& error) {
      errors.push_back(error.what());
    }
  }
  if (!errors.empty()) {
    std::string joined = file.string() + ": ";
    for (std::size_t i = 0; i < errors.size(); ++i) joined += (i ? "; " : "") + errors[i];
    return Status::failure(joined);
  }
  return result;
}

}  // namespace lastcut::daemon
