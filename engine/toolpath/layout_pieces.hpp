#pragma once
// From a nesting layout to the pieces the toolpath planner cuts: every placement's shape, marks and
// drawn lines moved to where the layout puts them (placed_shape / place_point of engine/nest/layout.hpp).
// A layout on hides may use several hides (and copies of one hide); each is a separate sheet on
// the table, so pieces are taken from one sheet at a time.
#include <filesystem>
#include <vector>

#include "engine/nest/layout.hpp"
#include "engine/nest/nest_problem.hpp"
#include "engine/toolpath/placed_piece.hpp"

namespace lastcut {

// One sheet of material: a hide copy (bin id, copy) or, for strip packing, the strip (bin -1).
struct SheetRef {
  int bin = -1;
  int copy = 0;
  bool operator==(const SheetRef&) const = default;
};

// The sheets the layout uses, in order of first appearance.
std::vector<SheetRef> sheets_in_layout(const Layout& layout);

// The pieces placed on `sheet`, in layout order. Throws EngineError for a placement of an item the
// instance does not have, or with a rotation or position that is not a finite number.
std::vector<PlacedPiece> placed_pieces(const Layout& layout, const NestInstance& instance, const SheetRef& sheet);

struct LayoutFile {
  NestInstance instance;
  Layout layout;
};

// Reads a self-contained layout JSON written by the nester (engine/nest/nest_json.hpp).
// Throws EngineError when it cannot be read or is not a layout.
LayoutFile read_layout_file(const std::filesystem::path& path);

}  // namespace lastcut
