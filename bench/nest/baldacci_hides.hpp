#pragma once
// The hides of one Baldacci et al. (2014) leather instance (jagua-rs JSON, ../shared/data/nesting/leather)
// as real hides in millimetres, for benchmarks that nest real shoe pieces on them (piece_yield_bench).
// The instance's units are not millimetres (a hide is ~10000 x 9000 units); each coordinate is scaled
// by mm_per_unit. The files give no grain: each hide gets a backbone along the principal axis of its
// outline (the axis of largest second moment of area), which is where a hide's backbone runs on a
// hide spread flat, longer along the animal than across it. Quality zones and holes as in the file.
#include <filesystem>
#include <vector>

#include "engine/core/polygon.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut::bench {

// The direction (deg, in (-90, 90]) of the principal axis with the larger second moment of area of
// the simple polygon, taken about its centroid. Throws EngineError when the polygon has no area.
double principal_axis_deg(const Polygon2& outline);

// Every bin of the instance file scaled to mm (ids 0.., names "<instance> hide <bin id>"), each
// checked as a hide file is (check_hide: rings simple, holes and zones inside, 0.05..10 m^2).
// Throws EngineError naming the file.
std::vector<Bin> baldacci_hides(const std::filesystem::path& file, double mm_per_unit);

// Outline minus holes (mm^2): the area the utilisation is measured against.
double usable_area_mm2(const Bin& hide);

}  // namespace lastcut::bench
