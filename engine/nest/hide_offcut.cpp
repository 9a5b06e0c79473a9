#include "engine/nest/hide_offcut.hpp"

#include <cmath>

#include <polyclipping/clipper.hpp>

#include "engine/core/dxf_document.hpp"
#include "engine/nest/clipper_paths.hpp"

namespace lastcut {
namespace {

constexpr double kScale = 100.0;             // integer units per mm (0.01 mm)
constexpr double kArcTolerance_mm = 0.05;    // rounded corners of grown pieces

}  // namespace

Offcut hide_offcut(const Layout& layout, const NestInstance& instance, int bin_id, double gap_mm) {
  const double gap = gap_mm >= 0 ? gap_mm : instance.gap_mm;
  const Bin& bin = find_bin(instance, bin_id);
  using nest_detail::to_path;
  ClipperLib::Paths pieces;
  for (const Placement& p : layout.placements) {
    if (p.bin != bin_id || p.copy != 0) continue;
    ClipperLib::Path path = to_path(placed_shape(find_item(instance, p.item), p).points, kScale);
    if (!ClipperLib::Orientation(path)) ClipperLib::ReversePath(path);
    pieces.push_back(std::move(path));
  }
  ClipperLib::Paths grown;
  ClipperLib::ClipperOffset offset(2.0, kArcTolerance_mm * kScale);
  offset.AddPaths(pieces, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  offset.Execute(grown, gap * kScale);

  ClipperLib::Clipper clipper;
  clipper.AddPath(to_path(bin.outer.points, kScale), ClipperLib::ptSubject, true);
  for (const Polygon2& hole : bin.holes) clipper.AddPath(to_path(hole.points, kScale), ClipperLib::ptClip, true);
  clipper.AddPaths(grown, ClipperLib::ptClip, true);
  ClipperLib::Paths left;
  clipper.Execute(ClipperLib::ctDifference, left, ClipperLib::pftNonZero, ClipperLib::pftNonZero);

  Offcut offcut;
  for (const ClipperLib::Path& path : left) {
    Polygon2 ring;
    ring.points = nest_detail::from_path(path, kScale);
    const double area = signed_area(ring);
    offcut.area_mm2 += area;
    (area > 0 ? offcut.outers : offcut.holes).push_back(std::move(ring));
  }
  return offcut;
}

std::string offcut_dxf(const Offcut& offcut) {
  DxfDocument dxf(DxfVersion::R12, {{"OFFCUT", 3}, {"OFFCUT_HOLE", 1}});
  for (const Polygon2& ring : offcut.outers) dxf.polyline("OFFCUT", ring.points, true);
  for (const Polygon2& ring : offcut.holes) dxf.polyline("OFFCUT_HOLE", ring.points, true);
  return dxf.str();
}

}  // namespace lastcut
