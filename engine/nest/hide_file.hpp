#pragma once
// Hide files: one leather hide as a digitizer or an operator writes it, read into a nesting Bin
// (millimetres) plus what the cutting room knows about it. See docs/hides.md.
//
//   DXF   layer HIDE      one closed polyline: the hide's outline
//         layer HOLE      closed polylines: defects and cut-outs (nothing is cut there)
//         layer ZONE_<q>  closed polylines: leather of quality grade q (an integer; lower = worse,
//                         as in the jagua-rs / Baldacci instances); leather outside every zone is
//                         the best grade
//         layer BACKBONE  one LINE (or open two-point polyline) from tail to neck: the grain
//         $INSUNITS 4 mm, 5 cm, 6 m, 1 inch, absent/0 read as mm; other units are refused.
//         Arcs (polyline bulges) are flattened within 0.01 mm. Other layers are ignored.
//   JSON  the jagua-rs bin layout of ../shared/data/nesting/leather: {"bins": [one bin]} (items,
//         if any, are ignored) or the bin object itself ({"shape": {"type": "polygon", "data":
//         {"outer", "inner"}}, "zones": [{"quality", "shape"}]}); optional "name", "backbone_deg",
//         and "units": "mm" (default) | "cm" | "m" | "in".
//   Sidecar <stem>.toml beside the hide file, all keys optional: id (text; default: the file's
//         stem), material, cutter, thickness_mm (0.2..20). Unknown keys are refused.
//
// Refused, each with one line naming the file: unreadable or unparsable file, no outline, an open
// or self-intersecting outline (or hole, or zone), a hole or zone more than 10 % outside the outline
// (a little over the edge is harmless: there is no leather there),
// unknown units, an area outside 0.05..10 m^2 (wrong units, or not a hide).
#include <filesystem>
#include <optional>
#include <string>

#include "engine/nest/nest_problem.hpp"

namespace lastcut {

struct HideFile {
  Bin bin;                // outline, holes, zones, backbone (mm); bin.name = hide_id, bin.id = 0
  std::string hide_id;    // the sidecar's id, else the file's stem
  std::string material;   // "" when the sidecar does not say
  std::string cutter;     // "" when the sidecar does not say
  std::optional<double> thickness_mm;
  double area_m2 = 0;     // inside the outline
  double usable_area_m2 = 0;  // outline minus holes
};

// Reads a .dxf or .json hide file and its sidecar <stem>.toml when present. Throws EngineError.
HideFile read_hide_file(const std::filesystem::path& path);

// The sidecar's keys into `hide` (id, material, cutter, thickness_mm). Throws EngineError.
void read_hide_sidecar(const std::filesystem::path& sidecar, HideFile& hide);

// The sidecar that belongs to a hide file: <stem>.toml in the same folder (may not exist).
std::filesystem::path hide_sidecar_path(const std::filesystem::path& hide_file);

// Checks a hide read by any reader: rings closed and simple, holes and zones at least 90 % inside the outline,
// area within 0.05..10 m^2. `source` names the file in the refusal. Throws EngineError.
void check_hide(const Bin& bin, const std::string& source);

// Limits of a plausible hide (m^2): below, not a hide; above, wrong units.
inline constexpr double kSmallestHide_m2 = 0.05;
inline constexpr double kLargestHide_m2 = 10.0;

}  // namespace lastcut
