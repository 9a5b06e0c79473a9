#pragma once
// The picture `lastcut style check` draws: a style's pieces where they lie on the two flattened halves
// of a last (the forme a pattern maker draws on), medial left and lateral right, each heel left and toe
// right as scan_to_molds places them. Each piece's region is filled in its own colour with its name at
// its label; the style lines are drawn over them, and the half's own edges (feather line, top edge,
// front and back seam) round each half.
//
// For a reader as much as a viewer, every element says what it is: `class="piece-region"
// data-piece="NAME"` (one path per piece, its rings on both halves), `class="piece-name"` (one text per
// piece), `class="style-line" data-line="NAME"` (one polyline per stretch of a line on a half),
// `class="edge" data-edge="feather|top|seam_front|seam_back"` and `class="half-name"`.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/piece_formes.hpp"
#include "engine/style/style_transfer.hpp"

namespace lastcut {

struct StyleCheckSheet {
  std::string title;
  std::array<const SegmentResult*, 2> halves{};           // medial, lateral
  std::vector<PieceForme> pieces;
  std::vector<std::optional<TransferredPoint>> labels;    // per piece, where its name goes (none: not written)
  std::vector<std::pair<std::string, TransferredCurve>> lines;  // the style lines on the same last
};

// Throws EngineError (one line) when the file cannot be written.
void write_style_check_svg(const std::filesystem::path& path, const StyleCheckSheet& sheet);

}  // namespace lastcut
