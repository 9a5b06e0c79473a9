#pragma once
// The files `lastcut flatten` and the daemon leave for every scan (the contract other tools read):
//   OUT/NAME-3d.obj    the 3D triangles that were flattened (mm)
//   OUT/NAME-flat.obj  the same vertices in the same order as "v u v 0", the same faces
//   OUT/NAME.dxf       the mold: outline on layer CUT, notches on layer MARK (engine/mold/mold_dxf.hpp)
//   OUT/NAME.svg       the mold over a stretch heat map with a legend (engine/mold/mold_svg.hpp)
//   OUT/report.json    see scan_report_json; written last (durably, engine/core/durable_file.hpp),
//                      so its presence means every other file is complete
// for every segment NAME (medial and lateral, or patch).
#include <filesystem>
#include <nlohmann/json.hpp>

#include "engine/scan/scan_to_molds.hpp"

namespace lastcut {

// Creates out_dir if needed and returns the report it wrote (scan_report_json). Throws EngineError
// when a file cannot be written.
nlohmann::json write_scan_outputs(const ScanResult& result, const std::filesystem::path& out_dir);

// {"input", "units": "mm", "side" (null: not segmented, or a symmetric last with no side named),
//  "seconds_total", "intake": {...}, "notes": [...], "warnings": [...] (also among the notes),
//  "repairs": [{"kind": "hole closed", "across_mm", "patch_vertices", "patch": "faired rings" | "fan"}],
//  "segments": [{"name", "triangles", "vertices", "flipped", "D_angle", "D_area", "area_3d_mm2",
//  "area_2d_mm2", "area_error_pct", "boundary_3d_mm", "boundary_2d_mm", "boundary_error_pct",
//  "max_stretch", "p95_stretch", "seconds_flatten", "iterations", "converged", "outline_points",
//  "mold_width_mm", "mold_height_mm", "files": {...}}],
//  "quality": the gate's verdict (MoldQuality::to_json, engine/scan/mold_quality_gate.hpp),
//  "profile": [{"stage", "seconds"}, ...]}: wall seconds per stage in the order they ran, from reading
//  the scan to writing the pictures (write_scan_outputs adds the writing stages)
nlohmann::json scan_report_json(const ScanResult& result);

}  // namespace lastcut
