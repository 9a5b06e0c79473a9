#pragma once
// Scanner noise taken off a scan before it is segmented and flattened, only where the scan needs
// it. Noise makes a surface longer than the last it was scanned from (every bump adds area), so
// molds of a noisy scan come out a few millimetres too large, and on thin triangles it folds them.
//
// Method: Taubin's lambda|mu smoothing, G. Taubin, "A signal processing approach to fair surface
// design", SIGGRAPH 1995: pairs of umbrella steps, one smoothing (lambda = 0.5) and one inflating
// (mu = -0.53), a low-pass filter over the mesh that removes vertex-scale noise without shrinking
// the last (plain Laplacian smoothing, and the bilateral filter of Fleishman et al. 2003 tried
// first, pull a curved surface inwards: on a 16k-triangle scan the molds came out 1-2 mm short).
// Adaptations:
//   - the umbrella step moves a vertex along its normal only, so the filter changes the shape and
//     nothing else; with the smoothing step the vertex also moves half way to its 1-ring's centroid
//     in the tangent plane (at most a quarter of the mean edge), which unfolds the triangles a
//     scanner's point error folded without moving the surface;
//   - a vertex on the scan's boundary (an open hole) does not move: the hole filler needs its rim.
// Need: estimated_noise_mm is the median over vertices of the jump of the umbrella height between
// a vertex and its neighbours (a second difference: smooth curvature cancels, noise does not),
// away from the scan's boundary (a rim vertex's umbrella is one-sided);
// denoise_scan does nothing below DenoiseOptions::min_noise_mm.
#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

struct DenoiseOptions {
  double min_noise_mm = 0.03;  // estimated noise below this: the scan is left as it is
  int passes = 8;  // lambda|mu pairs
};

struct DenoiseReport {
  double noise_before_mm = 0;
  double noise_after_mm = 0;
  int passes = 0;  // 0: not needed
};

// A robust noise estimate (mm) of the scan's surface; mesh: #V x 3 mm, topology of mesh.
double estimated_noise_mm(const TriMesh& mesh, const MeshTopology& topology);

// Moves the vertices of `mesh` (faces unchanged) when its estimated noise exceeds the threshold.
DenoiseReport denoise_scan(TriMesh& mesh, const MeshTopology& topology, const DenoiseOptions& options = {});

}  // namespace lastcut
