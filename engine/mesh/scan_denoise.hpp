#pragma once
// Scanner noise taken off a scan before it is segmented and flattened, only where the scan needs
// it. Noise makes a surface longer than the last it was scanned from (every bump adds area), so
// molds of a noisy scan come out a few millimetres too large, and on thin triangles it folds them.
//
// Method: bilateral mesh denoising, S. Fleishman, I. Drori, D. Cohen-Or, "Bilateral mesh
// denoising", ACM Transactions on Graphics 22(3) (SIGGRAPH 2003) 950-953. Each vertex moves along
// its (mollified) normal by the weighted mean height of its neighbours over its tangent plane; the
// weights fall with distance (closeness, sigma_c) and with the height itself (similarity,
// sigma_s), so noise is averaged away while a real edge (the top cut's rim, the feather line) is
// kept: points across an edge are far above the plane and weigh nothing. Adaptations:
//   - neighbours are the 2-ring (the paper's radius 2 sigma_c with sigma_c = the mean edge);
//   - the normal is the area-weighted mean of the face normals over the 2-ring (the paper's
//     mollification), since a noisy vertex normal would steer the step sideways;
//   - sigma_s is the standard deviation of the heights in the neighbourhood, as in the paper, but
//     at least a tenth of the mean edge so a clean patch is not divided by zero;
//   - a vertex on the scan's boundary (an open hole) does not move: the hole filler needs its rim.
// Need: estimated_noise_mm is the median over vertices of the jump of the umbrella height between
// a vertex and its neighbours (a second difference: smooth curvature cancels, noise does not);
// denoise_scan does nothing below DenoiseOptions::min_noise_mm.
#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

struct DenoiseOptions {
  double min_noise_mm = 0.03;  // estimated noise below this: the scan is left as it is
  int passes = 3;
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
