#pragma once
// generate_last: a realistic synthetic shoe-last scan for samples, tests and benchmarks.
// The solid (LastShape: plan outline, sole line with heel pitch and toe spring, crowned instep,
// flat top cut, rounded feather line) is polygonised by marching tetrahedra and remeshed
// isotropically onto the exact surface to the requested triangle count (or, with LastSurface::Bezier,
// built as a C2 Bezier surface with a sharp flat top cut: bezier_last.hpp); then a simulated
// scanner adds normal noise, small holes and an arbitrary pose. Deterministic for the params.
//
//   #include "engine/lastgen/generate_last.hpp"
//   lastcut::LastParams params = lastcut::LastParams::for_eu_size(42, lastcut::FootSide::Left);
//   params.noise_mm = 0.2;
//   lastcut::GeneratedLast last = lastcut::generate_last(params);
//   lastcut::write_stl_binary("last.stl", last.mesh);
#include "engine/lastgen/last_params.hpp"
#include "engine/mesh/write_mesh.hpp"

namespace lastcut {

// Throws EngineError when validate(params) refuses them.
GeneratedLast generate_last(const LastParams& params);

}  // namespace lastcut
