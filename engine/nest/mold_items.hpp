#pragma once
// Nest items from the molds `lastcut flatten` writes (engine/mold): one item per mold with its
// notches as marks, optionally a mirrored twin for the other foot, on a roll of given width.
#include <functional>
#include <optional>
#include <string>
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
  // Hides: the toe/vamp of a shoe shows on the finished shoe and needs better leather. With
  // toe_region_min_quality > 0 every mold with "toe" and "heel" notches gets a QualityRegion: the
  // part of its outline within toe_region_fraction x (toe-heel distance) of the toe notch, measured
  // along the heel-to-toe axis; that region may only lie on zones of quality >= toe_region_min_quality.
  int toe_region_min_quality = 0;
  double toe_region_fraction = 0.4;
  // The text on the piece; `twin` is the mirrored copy. Empty: the mold's name, "(other foot)" for a twin.
  std::function<std::string(const Mold& mold, bool twin)> label;
};

// Items numbered 0.. in mold order (each mold, then its twin). The twin is the mold mirrored
// x -> -x with its notches, outline made counter-clockwise again. Throws EngineError when there
// are no molds, no copies, or an outline is degenerate.
std::vector<NestItem> items_from_molds(const std::vector<Mold>& molds, const MoldNestSpec& spec);

// The toe region of one item (see MoldNestSpec) from its "toe" and "heel" marks, in the item's frame;
// nullopt when a mark is missing or the region is empty. fraction in (0, 1].
std::optional<QualityRegion> toe_region(const NestItem& item, double fraction, int min_quality);

// The items on a strip of spec.roll_width_mm. Throws EngineError as items_from_molds, or on a bad width.
NestInstance instance_from_molds(const std::vector<Mold>& molds, const MoldNestSpec& spec, const std::string& name);

}  // namespace lastcut
