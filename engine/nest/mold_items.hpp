#pragma once
// Nest items from the molds `lastcut flatten` writes (engine/mold): one item per mold with its
// notches as marks, optionally a mirrored twin for the other foot, on a roll of given width.
#include <optional>
#include <vector>

#include "engine/mold/mold.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

struct MoldNestSpec {
  double roll_width_mm = 1400;            // strip height
  int copies = 1;                         // demand of every mold (pairs of shoes to cut)
  bool mirrored_twins = false;            // add each mold mirrored (x -> -x) for the other foot
  std::vector<double> rotations_deg;      // empty = free rotation
  std::optional<double> grain_tolerance_deg;  // grain along the mold's x axis (heel to toe) within this
  double gap_mm = 0;
  double margin_mm = 0;
};

// Throws EngineError when there are no molds or an outline is degenerate.
NestInstance instance_from_molds(const std::vector<Mold>& molds, const MoldNestSpec& spec, const std::string& name);

}  // namespace lastcut
