#pragma once
// Molds as ASCII DXF, the exchange format of pattern CAD (LibreCAD, QCAD, cutter software).
// Written as DXF R12 (AC1009, the most widely read version), units millimetres ($INSUNITS 4):
//   layer CUT   one closed POLYLINE, the cutting outline (counter-clockwise)
//   layer MARK  one LINE per notch, from the outline inward kNotchLength_mm long, and a TEXT
//               with the notch name at its inner end
//   layer LABEL a TEXT with the mold name inside the outline
//   layer NET   one closed POLYLINE, the net line (the last's edge inside the allowance), only
//               when the mold has an allowance; drawn for the pattern maker, never cut
// The reader accepts what the writer writes, and also LWPOLYLINE outlines (R14+ files).
#include <filesystem>

#include "engine/mold/mold.hpp"

namespace lastcut {

// Throws EngineError when the file cannot be written.
void write_mold_dxf(const std::filesystem::path& path, const Mold& mold);

// Throws EngineError (one line naming the file) when the file is missing, not DXF, or holds no
// closed outline on layer CUT (or more than one). The outline is returned counter-clockwise.
Mold read_mold_dxf(const std::filesystem::path& path);

}  // namespace lastcut
