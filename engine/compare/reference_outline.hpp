#pragma once
// Reference patterns: the outline a shop trusts (a production pattern from pattern CAD, a traced
// wax-foil mold, an earlier lastcut mold), read in millimetres, counter-clockwise.
//   DXF  the closed LWPOLYLINE or POLYLINE of largest area on any layer (bulge arcs flattened
//        within 0.01 mm); a polyline whose last point repeats its first counts as closed.
//        $INSUNITS: 4 mm, 5 cm, 6 m, 1 inch; absent or 0 (unitless) is read as mm; any other
//        unit is refused. A photo-traced outline is exactly this: a DXF polyline.
//        A lastcut mold DXF (outline on layer CUT, notches on layer MARK) keeps its notch marks.
//   SVG  the closed <path d="..."> of largest area (commands M L H V C Q Z, absolute and
//        relative; curves flattened within 0.01 mm). Units: with a viewBox and width/height in
//        mm, cm, in, pt or px the user unit is width / viewBox width; otherwise a user unit is a
//        CSS pixel, 1/96 inch. y is flipped (SVG points down) so the pattern keeps its handedness.
//        transform attributes are refused (flatten them in the drawing program first).
// Size: at least 5 mm and at most 2000 mm across, at most 10 m around, at most 20,000 points. Outside
// that it is no shoe pattern (most often a drawing in other units than its header says), and the
// comparison, which samples the outline every 0.25 mm against every edge of the other, would run for
// minutes on it. Shape: the outline may not cross or touch itself (a crossing outline has no one
// area to compare); a point repeated in a row is not a crossing.
// Every refusal is an EngineError of one line that names the file.
#include <filesystem>
#include <string>

#include "engine/mold/mold.hpp"

namespace lastcut {

// Reads by extension (.dxf or .svg, any case). The Mold's name is the file's stem; marks are empty
// unless the file is a lastcut mold DXF.
Mold read_reference_outline(const std::filesystem::path& path);

// The two readers behind it (same rules, no extension check).
Mold read_dxf_outline(const std::filesystem::path& path);
Polygon2 read_svg_outline(const std::filesystem::path& path);

// Refuses (EngineError, one line starting with `source`) an outline outside the size and shape rules
// above.
void check_pattern_outline(const std::string& source, const Polygon2& outline);

// Largest-area closed ring of `rings` (each #P >= 3, mm), made counter-clockwise. Throws the
// "no closed outline" refusal naming `path` when there is none with area.
Polygon2 largest_closed_outline(const std::filesystem::path& path, std::vector<Polygon2> rings, int open_count);

// Sagitta tolerance for flattening arcs and curves (mm).
inline constexpr double kCurveTolerance_mm = 0.01;

}  // namespace lastcut
