#pragma once
// lastcut's nester: strips (fixed height, shortest length) and hides/sheets (fewest hides, every
// piece if possible, compact within each hide). See strip_nester.hpp and hide_nester.hpp for the
// methods and docs/nesting.md for the whole picture.
#include "engine/nest/layout.hpp"
#include "engine/nest/nest_options.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

// The one entry to nesting for every front door (`lastcut nest`, lastcutd): checks the options,
// clusters complementary pairs on strips, nests, and runs the independent layout checker
// (layout_check.hpp) on the result. Throws EngineError on an instance that cannot be nested at all
// (no items, negative options) and when the checker refuses the layout (a bug, never cut).
// Pieces that do not fit are never dropped: they are listed in Layout::unplaced with a reason.
Layout nest(const NestInstance& instance, const NestOptions& options);

}  // namespace lastcut
