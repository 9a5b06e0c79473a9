#pragma once
// Seam lengths on both sides (issue 34, point 4, "the length of each seam on both pieces and their
// difference"): for every curve pieces are sewn along, the flattened length of the stretches of the
// pieces on one side and on the other. Which side a stretch is on follows from its direction: piece
// outlines run counter-clockwise, so the pieces on the two sides of a curve run along it opposite ways.
#include <string>
#include <vector>

#include "engine/style/piece_mold.hpp"
#include "engine/style/piece_notches.hpp"
#include "engine/style/piece_surface.hpp"

namespace lastcut {

struct SeamReport {
  std::string seam;                          // the line's name, "front seam", "back seam"
  std::vector<std::string> one_side, other_side;  // the pieces
  double one_side_mm = 0, other_side_mm = 0;      // their net stretches' flattened lengths along it
  double length_3d_mm = 0;                        // the same stretches of one side in 3D (mid-surface of a thick piece)
  double difference_mm() const { return one_side_mm - other_side_mm; }
};

// pieces: each piece's surface and mold, in the same order. Curves with pieces on one side only are left out.
std::vector<SeamReport> seam_reports(const std::vector<SewnCurve>& curves,
                                     const std::vector<std::pair<const PieceSurface*, const PieceMold*>>& pieces);

}  // namespace lastcut
