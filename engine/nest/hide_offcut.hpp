#pragma once
// What is left of a hide after its pieces are cut: the leather inside the outline, outside the
// holes, and farther than the gap (the knife's kerf and clearance) from every placed piece, for
// small parts later. Computed with Clipper's booleans and offsets (Clipper 6.4, Angus Johnson)
// on a 0.01 mm grid.
#include <string>
#include <vector>

#include "engine/nest/layout.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

struct Offcut {
  std::vector<Polygon2> outers;  // counter-clockwise, mm
  std::vector<Polygon2> holes;   // clockwise, mm: inside some outer (defects, cut pieces enclosed)
  double area_mm2 = 0;           // outers minus holes
};

// The offcut of hide `bin_id` (copy 0) in `layout`; pieces grown by gap_mm (< 0: the instance's gap).
Offcut hide_offcut(const Layout& layout, const NestInstance& instance, int bin_id, double gap_mm = -1);

// The offcut as an R12 DXF in mm: layer OFFCUT (outer rings), OFFCUT_HOLE (inner rings).
std::string offcut_dxf(const Offcut& offcut);

}  // namespace lastcut
