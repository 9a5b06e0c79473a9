#include "engine/compare/compare_report.hpp"

#include <cmath>
#include <numbers>

#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"

namespace lastcut {

namespace {

nlohmann::json xy(const Point2& p) { return nlohmann::json::array({p.x(), p.y()}); }

const char* source_of(const CornerMatch& corner) {
  if (corner.from_reference_mark) return "reference mark";
  return corner.found_sharp_corner ? "sharp corner" : "nearest outline point";
}

}  // namespace

nlohmann::json comparison_json(const Comparison& comparison, const CompareFiles& files, double tolerance_mm) {
  const OverlapAlignment& a = comparison.alignment;
  nlohmann::json corners = nlohmann::json::array();
  for (const auto& corner : comparison.corners)
    corners.push_back({{"name", corner.name},
                       {"margin_mm", corner.margin_mm},
                       {"mold_mm", xy(corner.mold_mm)},
                       {"reference_mm", xy(corner.reference_mm)},
                       {"source", source_of(corner)},
                       {"within_tolerance", corner.margin_mm <= tolerance_mm}});
  return {{"mold", {{"file", files.mold}, {"name", comparison.mold.name}, {"area_mm2", a.mold_area_mm2}}},
          {"reference",
           {{"file", files.reference}, {"name", comparison.reference_moved.name}, {"area_mm2", a.reference_area_mm2}}},
          {"intersection_area_mm2", a.intersection_area_mm2},
          {"overlap_pct", 100.0 * a.overlap_fraction()},
          {"motion",
           {{"mirrored", a.motion.mirrored},
            {"rotation_deg", a.motion.rotation_rad * 180.0 / std::numbers::pi},
            {"translation_mm", xy(a.motion.translation_mm)}}},
          {"corners", corners},
          {"max_margin_mm", comparison.max_margin_mm()},
          {"tolerance_mm", tolerance_mm},
          {"within_tolerance", comparison.max_margin_mm() <= tolerance_mm},
          {"hausdorff_mm", comparison.deviation.hausdorff_mm},
          {"mean_distance_mm", comparison.deviation.mean_mm},
          {"mold_to_reference_max_mm", comparison.deviation.mold_to_reference_max_mm},
          {"reference_to_mold_max_mm", comparison.deviation.reference_to_mold_max_mm}};
}

nlohmann::json write_comparison(const Comparison& comparison, const CompareFiles& files, double tolerance_mm,
                                const std::filesystem::path& folder, const std::string& stem) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw EngineError("cannot create " + folder.string() + ": " + error.message());
  const nlohmann::json json = comparison_json(comparison, files, tolerance_mm);
  for (const auto& [name, text] : {std::pair{stem + ".svg", comparison_svg(comparison, tolerance_mm)},
                                   std::pair{stem + ".json", json.dump(2) + "\n"}}) {
    const Status status = write_file_durably(folder / name, text);
    if (!status.ok()) throw EngineError(status.error());
  }
  return json;
}

}  // namespace lastcut
