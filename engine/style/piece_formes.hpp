#pragma once
// Where a style's cut pieces lie in the flattenings of the last's two halves, to draw them on the forme
// (`lastcut style check`). Each triangle of a piece's 3D surface (piece_surface.hpp) is found on the half
// it was cut from (the closest point of either half's surface to its centroid, triangle_locator.hpp), its
// corners are carried into that half's flattening by their barycentric weights, and a piece's triangles on
// one half are joined there (Clipper union). Drawing what was cut, rather than the regions it was cut from,
// shows a gap or an overlap between pieces where the cutting made one.
#include <polyclipping/clipper.hpp>

#include <array>
#include <string>
#include <vector>

#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/style_pieces.hpp"

namespace lastcut {

struct PieceForme {
  std::string name;
  // Per half (0 medial, 1 lateral): outer rings and holes, in kClipperUnitsPerMm of the half's UV; empty
  // where the piece does not lie on that half.
  std::array<ClipperLib::Paths, 2> rings;
};

// A piece's point farther than this from both halves (mm) was not cut from them.
inline constexpr double kPieceOffHalves_mm = 0.01;

// halves: the medial and lateral SegmentResult the pieces were cut from. Throws EngineError (one line,
// naming the piece) when a piece's triangle lies on neither half.
std::vector<PieceForme> piece_formes(const std::array<const SegmentResult*, 2>& halves,
                                     const std::vector<StylePieceResult>& pieces);

}  // namespace lastcut
