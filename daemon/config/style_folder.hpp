#pragma once
// A style folder as a shop keeps it (issue 34): `style.toml` beside the lines drawn on the reference
// last. Every key is checked, unknown keys are refused with their line (a typo must not fall back to
// a default), and one run reports every mistake of the file.
//
//   name = "derby"
//   lines = "lines.obj"                  # style lines on the reference last (OBJ polylines, mm), or
//   # forme = "forme.dxf"                # the lines and piece texts drawn on its forme (`lastcut style new`;
//                                        # docs/style-authoring.md): then a [[piece]] has no label
//   thickness_mm = 0.0                   # the pieces' material (0..10 mm): each is flattened from its
//                                        # mid-surface, half of it off the last (piece_thickness.hpp); 0: off
//   [reference]                          # the last the style was drawn on: a scan beside style.toml ...
//   scan = "reference.stl"
//   side = "right"
//   # ... or a generated last: generated_eu_size = 42 (with side), generated_triangles = 40000
//   [allowances]                         # mm; shoemaking's defaults
//   lasting = 18.0
//   folding = 5.0
//   underlay = 8.0
//   butted = 0.0
//   [[line]]                             # which piece lies under its neighbour along a line
//   name = "vamp"
//   under = "vamp"
//   [[seam_cut]]                         # stretches of the centre seams the pieces are cut apart along
//   seam = "front"                       # "front" or "back"
//   from_line = "vamp"                   # from where that line crosses it up to the top edge (omit: all of it)
//   [[piece]]
//   name = "vamp"
//   label = [240.0, 0.0, 45.0]           # a point inside the piece on the reference last, its scan's frame
//   material = "upper leather"
//   quantity = 1                         # per shoe
//   grain_deg = 0.0                      # grain line from the heel-to-toe axis (-180..180)
//   grain_tolerance_deg = 10.0           # on a hide: grain along the backbone within this (0..90);
//                                        # absent: the material's grain_tolerance_deg
//   min_quality = 3                      # lowest leather grade (0..100); absent: the material's
//   thickness_mm = 1.2                   # this piece's material (0..10 mm); absent: the style's thickness_mm
#include <filesystem>
#include <optional>

#include "engine/core/foot_side.hpp"
#include "engine/core/status.hpp"
#include "engine/lastgen/last_params.hpp"
#include "engine/style/forme_drawing.hpp"
#include "engine/style/style_definition.hpp"

namespace lastcut::daemon {

struct StyleFolder {
  StyleDefinition style;
  std::filesystem::path reference_scan;      // empty when generated
  std::optional<LastParams> generated_reference;
  FootSide reference_side = FootSide::Right;
  // A style drawn on the forme: its drawing, read but not yet on the last (style.lines empty, pieces
  // without labels) until lift_forme_style (style_forme.hpp) lifts it with the reference's scan.
  std::optional<FormeDrawing> forme;
};

// Reads `folder`/style.toml and the lines file it names. The error is one line: every problem found,
// separated by "; ".
Result<StyleFolder> read_style_folder(const std::filesystem::path& folder);

}  // namespace lastcut::daemon
