#pragma once
// The record of a comparison: compare.json for programs and the job report, compare.svg for the
// operator (fields and picture described in docs/compare.md).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/compare/compare_outlines.hpp"

namespace lastcut {

struct CompareFiles {
  std::string mold;       // as given by the user, for the record
  std::string reference;
};

// {"mold": {"file", "name", "area_mm2"}, "reference": {"file", "name", "area_mm2"},
//  "intersection_area_mm2", "overlap_pct", "motion": {"mirrored", "rotation_deg", "translation_mm": [x, y]},
//  "corners": [{"name", "margin_mm", "mold_mm": [x, y], "reference_mm": [x, y], "source", "within_tolerance"}],
//  "max_margin_mm", "tolerance_mm", "within_tolerance", "hausdorff_mm", "mean_distance_mm",
//  "mold_to_reference_max_mm", "reference_to_mold_max_mm"}
// source: "reference mark", "sharp corner" or "nearest outline point" (see outline_corners.hpp).
nlohmann::json comparison_json(const Comparison& comparison, const CompareFiles& files, double tolerance_mm);

// The picture (true size, mm, y up on paper): the moved reference in grey, the mold's edge
// coloured by its signed deviation (legend), each corner margin as a line labelled in mm, red
// beyond tolerance_mm.
std::string comparison_svg(const Comparison& comparison, double tolerance_mm);

// Writes `stem`.json and `stem`.svg into `folder` (created if missing), durably. Throws
// EngineError when a file cannot be written. Returns the JSON written.
nlohmann::json write_comparison(const Comparison& comparison, const CompareFiles& files, double tolerance_mm,
                                const std::filesystem::path& folder, const std::string& stem);

}  // namespace lastcut
