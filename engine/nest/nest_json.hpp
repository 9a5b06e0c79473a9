#pragma once
// JSON I/O for nesting.
//
// Instances: the layout of the jagua-rs / sparrow benchmark files (/work/shared/data/nesting):
//   strip:  {"name", "strip_height", "items": [{"id", "demand", "allowed_orientations": [deg..]
//            (absent = free rotation), "shape": {"type": "simple_polygon", "data": [[x,y]..]}}]}
//   hides:  {"name", "bins": [{"id", "stock", "cost", "shape": {"type": "polygon", "data":
//            {"outer": [[x,y]..], "inner": [[[x,y]..]..]}}, "zones": [{"quality", "shape"}]}],
//            "items": [... "min_quality" ...]}
// plus lastcut's own optional fields: items "allow_mirror", "grain_deg", "grain_tolerance_deg",
// "label", "marks": [{"name", "from": [x,y], "to": [x,y]}], "drawn_lines": [[[x,y], [x,y]..]..]
// (pen lines, >= 2 points each); instance "gap_mm", "margin_mm".
// A shape may also be a bare [[x,y]..] list. A repeated closing point is dropped.
//
// Layouts (read by `lastcut toolpath` and the daemon):
//   {"instance", "strip_length" (strip only), "utilisation",
//    "placements": [{"item", "bin" (hides only), "copy" (only when > 0), "rotation_deg", "mirrored", "x", "y"}],
//    "unplaced": [{"item", "count", "reason"}],
//    "items": [{"id", "shape", "label", "marks", "drawn_lines" (when any), "demand", "allowed_rotations_deg", "allow_mirror",
//               "grain_deg", "grain_tolerance_deg", "min_quality"}],
//    "strip_height" (strip) | "bins": [{"id", "outer", "holes", "zones", "stock", "cost"}],
//    "gap_mm", "margin_mm"}
// so that a layout file is self-contained: the cut-file stage and the checker need nothing else.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/nest/layout.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

// Parses an instance; `source` names it in error messages. Throws EngineError on bad input
// (missing fields, fewer than 3 points, zero area, non-finite numbers, duplicate ids, ...).
NestInstance instance_from_json(const nlohmann::json& json, const std::string& source);
// Reads an instance file. Throws EngineError when it cannot be read or parsed.
NestInstance read_nest_instance(const std::filesystem::path& path);
// The instance in the same layout instance_from_json reads.
nlohmann::json instance_to_json(const NestInstance& instance);

// One bin (hide) in the instance's bin layout; `source` names it in errors. Throws EngineError.
Bin bin_from_json(const nlohmann::json& json, const std::string& source);

// Items alone, {"items": [...]} in the instance's item layout: the pieces of one job waiting for a
// batch (the daemon keeps them in the job folder). items_from_json throws EngineError on bad input.
nlohmann::json items_to_json(const std::vector<NestItem>& items);
std::vector<NestItem> items_from_json(const nlohmann::json& json, const std::string& source);

// The layout with the instance geometry embedded (see above).
nlohmann::json layout_to_json(const Layout& layout, const NestInstance& instance);
// The layout part (placements, unplaced, length, utilisation). Throws EngineError on bad input.
Layout layout_from_json(const nlohmann::json& json);
// The instance embedded in a layout written by layout_to_json. Throws EngineError on bad input.
NestInstance instance_from_layout_json(const nlohmann::json& json);

// Files. Throw EngineError when the file cannot be read, parsed or written.
void write_layout(const std::filesystem::path& path, const Layout& layout, const NestInstance& instance);
nlohmann::json read_json_file(const std::filesystem::path& path);

}  // namespace lastcut
