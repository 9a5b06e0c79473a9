#pragma once
// One bicubic Bezier patch per face of a quad control mesh, after thesis section 3.2 (M. Sabaliauskas,
// "Computerized modeling technology of unique footwear surface manufacturing design", doctoral thesis
// summary, Vilnius University 2017) and M. Sabaliauskas, "An algorithm for approximation of Bezier
// surfaces for special case of quadrangular grid", Computational Science and Techniques 3(2), 2015.
// The patch construction is that of C. Loop and S. Schaefer, "Approximating Catmull-Clark subdivision
// surfaces with bicubic patches", ACM Transactions on Graphics 27(1), 2008 (ACC): every Bezier point is
// a local average around one control vertex v of valence n with edge neighbours e_j and face-diagonal
// neighbours f_j (counter-clockwise):
//   corner    P   = (n^2 v + 4 sum e_j + sum f_j) / (n (n + 5))       Catmull-Clark limit position
//   interior  I_j = (n v + 2 (e_j + e_j+1) + f_j) / (n + 5)
//   edge      E_i = P + ((M_i - P) . d_i) d_i,  M_i = (I_i-1 + I_i) / 2,  d_i = t_i / |t_i|
// i.e. the direction of the Catmull-Clark limit tangent t_i (so all edge points at v lie in the limit
// tangent plane) with the length of the regular rule M_i (for n = 4, E_i = M_i exactly, which we use).
// The limit tangent mask is that of Halstead, Kass and DeRose, "Efficient, fair interpolation using
// Catmull-Clark surfaces", SIGGRAPH 1993:
//   t_i = sum_j A_n cos(2 pi (j-i)/n) e_j + (cos(2 pi (j-i)/n) + cos(2 pi (j-i+1)/n)) f_j,
//   A_n = 1 + cos(2 pi/n) + cos(pi/n) sqrt(2 (9 + cos(2 pi/n))).
// The length rule is ours (Loop & Schaefer scale the tangent differently); on the valence-3 corners
// of a cube sphere (radius 20 mm, control edges ~ 8 mm) it keeps the samples within 0.12 mm of the
// Catmull-Clark limit surface (tests/subdiv/catmull_clark_oracle_test.cpp), where scaling t_i to a
// third of a planar ring of unit edges was 4 times farther off (0.48 mm).
// For n = 4 these are the Bezier points of the uniform bicubic B-spline patch of the face's 4 x 4
// control points (the standard B-spline-to-Bezier conversion), i.e. the Catmull-Clark limit surface
// (Catmull & Clark 1978; Stam 1998).
//
// Boundary (vertex with k edges, k - 1 faces, boundary neighbours e_0 and e_k-1): the rule of mirrored
// ghost points, p_ghost = 2 v - p_inner across the boundary, which makes the boundary curve the cubic
// B-spline of the boundary polygon (the Catmull-Clark boundary rule):
//   k = 2 (corner):  P = v, E = v + (e - v) / 3, I = (4 v + 2 e_0 + 2 e_1 + f_0) / 9
//   k >= 3:          P = (4 v + e_0 + e_k-1) / 6, boundary E = P +- (e_0 - e_k-1) / 6,
//                    I_j as above with n = 2 (k - 1) (the valence of the mirrored vertex),
//                    inner E_i = (I_i-1 + I_i) / 2
// For k = 2 and k = 3 this is exactly the B-spline of the grid extended by mirrored ghost points.
//
// Continuity: C2 across an edge whose two patches are regular (their four corners of valence 4, or on
// the boundary of valence 3 or 2); C1 across an edge whose two end vertices are regular; C0 with a
// common tangent plane at the vertex across the edges at an extraordinary vertex (valence != 4) and
// at irregular boundary vertices (k >= 4).
#include <Eigen/Core>
#include <array>
#include <utility>
#include <vector>

#include "engine/subdiv/quad_mesh.hpp"

namespace lastcut {

// b[i + 4 j]: Bezier point (i along u, j along v), mm. Face corners Q0, Q1, Q2, Q3 sit at
// (u, v) = (0,0), (1,0), (1,1), (0,1).
struct BezierPatch {
  std::array<Eigen::Vector3d, 16> b;
  const Eigen::Vector3d& at(int i, int j) const { return b[static_cast<size_t>(i + 4 * j)]; }
};

// A patch's position and derivatives at (u, v): mm, mm per unit parameter, mm per unit parameter^2.
struct PatchPoint {
  Eigen::Vector3d position, du, dv, duu, duv, dvv;
};

// #Q patches of a quad mesh whose topology was built by build_quad_topology.
std::vector<BezierPatch> build_bezier_patches(const QuadMesh& mesh, const QuadTopology& topology);

// The same nets as weights of the control vertices: b[i + 4 j] = sum of weight x V.row(vertex) over
// the entry's (vertex, weight) pairs. Exact where build_bezier_patches is linear in V: everywhere
// but at the edge points of an extraordinary interior vertex (valence != 4), which take the regular
// rule's average M_i here instead of its projection onto the limit tangent (the linear part a
// least-squares fit of V can use; bezier_patches.cpp).
struct PatchWeights {
  std::array<std::vector<std::pair<int, double>>, 16> b;
};
std::vector<PatchWeights> bezier_patch_weights(const QuadMesh& mesh, const QuadTopology& topology);

// Position and first and second derivatives of the patch at (u, v) in [0, 1]^2.
PatchPoint evaluate_patch(const BezierPatch& patch, double u, double v);
// Position only (the sampler's inner loop).
Eigen::Vector3d patch_position(const BezierPatch& patch, double u, double v);

}  // namespace lastcut
