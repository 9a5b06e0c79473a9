#pragma once
// Sampling the Bezier surface of a quad control mesh (bezier_patches.hpp) with any detail n >= 1:
// each control face becomes an n x n grid of quads at the patch parameters (i / n, j / n). Samples on
// a shared edge or corner are one vertex, computed once (welded exactly), so the result is watertight
// where the control mesh is closed. Catmull-Clark reaches only n = 2^k; for n = 2^k on a regular
// region the samples are the Catmull-Clark limit positions of the k-times subdivided mesh.
//
//   QuadMesh control = read_quad_obj("last-quads.obj");
//   SubdividedSurface surface = subdivide_bezier(control, 5);
//   write_quad_obj("last.obj", surface.quads);
#include <vector>

#include "engine/core/tri_mesh.hpp"
#include "engine/subdiv/bezier_patches.hpp"
#include "engine/subdiv/quad_mesh.hpp"

namespace lastcut {

// The largest detail and the largest number of output quads subdivide_bezier accepts.
constexpr int kMaxSubdivisionDetail = 1024;
constexpr long long kMaxSubdividedQuads = 20'000'000;

// Where the samples sit in each face: Uniform at (i/n, j/n) (at n = 2^k the Catmull-Clark parameters), or
// EvenAtExtraordinary: near a control vertex of valence != 4 (not on the boundary) the parameters are warped
// so that the first sample segment along each edge leaving it is about as long as the edge's mean segment.
// The warp along an edge t -> t + a t (1 - t)^2 (a from the ratio |S'(0)| / chord of that edge, clamped to
// [-0.3, 0.5], monotone) is blended into the face by (1 - r)^2, r the parameter across; it vanishes on the
// face edges away from the vertex, so shared edges keep one set of samples.
enum class SampleSpread { Uniform, EvenAtExtraordinary };

struct SubdividedSurface {
  QuadMesh quads;  // #Q n^2 quads; vertices: used control corners, then n - 1 per edge, (n - 1)^2 per face
  // Per output vertex: the control face it was evaluated on and its (u, v) there (after the warp).
  std::vector<int> source_face;  // #V
  Eigen::MatrixXd source_uv;     // #V x 2
};

// Throws EngineError when n is outside 1..kMaxSubdivisionDetail, the output would exceed
// kMaxSubdividedQuads, or the control mesh is not an oriented 2-manifold of quads.
SubdividedSurface subdivide_bezier(const QuadMesh& control, int n, SampleSpread spread = SampleSpread::Uniform);

// How evenly a sampled surface spreads its samples along one control edge: the control vertices at
// the edge's ends (`from` starts its representative half-edge, QuadTopology::edge_half_edge) and the
// lengths (mm) of the edge's first and last sample segments over the mean of its n segments (both 1
// when the samples are evenly spaced along the sampled curve).
struct EdgeEndSpacing {
  int from = 0, to = 0;
  double first_ratio = 0.0, last_ratio = 0.0;
};
// One per control edge, in QuadTopology's edge order; `surface` is subdivide_bezier(control, n, ...).
std::vector<EdgeEndSpacing> edge_end_spacing(const QuadMesh& control, const SubdividedSurface& surface, int n);

// Each quad split into two triangles along its shorter diagonal (same vertices, counter-clockwise).
TriMesh triangulate_quads(const QuadMesh& quads);

}  // namespace lastcut
