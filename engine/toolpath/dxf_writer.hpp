#pragma once
// DXF (ASCII, AutoCAD 2000 group codes) of a cut program for CAD users: the pieces' outlines as
// closed LWPOLYLINEs on layer CUT, notches and landmarks as LINEs on layer MARK, the labels'
// single-stroke lettering as open LWPOLYLINEs on layer TEXT. Units mm ($INSUNITS 4). Geometry is
// what ends up on the leather (the blade-tip path), not the compensated holder path.
// Structure: HEADER ($ACADVER, $INSUNITS, $MEASUREMENT, $EXTMIN/$EXTMAX, $HANDSEED), TABLES (LTYPE
// CONTINUOUS, LAYER 0/CUT/MARK/TEXT), BLOCKS (empty), ENTITIES, EOF; every object carries a handle.
#include <string>

#include "engine/toolpath/cut_program.hpp"

namespace lastcut {

std::string write_dxf(const CutProgram& program);

}  // namespace lastcut
