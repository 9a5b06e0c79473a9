#pragma once
// The flat cap of the Bezier last's top cut: triangles inside the rim loop, all in the cut plane, with
// exactly the number of triangles the count leaves for it.
//
// The rim loop runs as four arcs of nu, nv, nu, nv segments (the side's cap cells at detail n). When the
// cap's share of the triangles allows no finer grid than those arcs (or exactly theirs), the cap is that
// nu x nv grid. Otherwise it is a finer Nu x Nv grid sized to the share (cells as large as the side's
// when the share is right), of which the outer ring is dropped: its inner (Nu - 2) x (Nv - 2) quads and
// one transition row of triangles zipped between the rim samples and the grid's outermost inner ring
// (at each step the shorter of the two possible diagonals, as in the classic contour stitching of
// H. Fuchs, Z. Kedem, S. Uselton, "Optimal surface reconstruction from planar contours", CACM 20(10),
// 1977, with the greedy shortest-diagonal rule instead of their optimum). Grids come from the bilinearly
// blended Coons patch of the four arcs (S. A. Coons, MIT MAC-TR-41, 1967) smoothed by uniform Laplacian
// steps. Triangles still missing come from splitting inner quads into four around their centre.
#include <Eigen/Core>
#include <vector>

namespace lastcut {

struct TopCapInput {
  const Eigen::MatrixXd* V = nullptr;  // positions of the side's vertices (mm); the loop indexes them
  std::vector<int> loop;               // the rim, 2 (nu + nv) vertices, corners at 0, nu, nu + nv, 2 nu + nv
  int nu = 0, nv = 0;
  Eigen::Vector3d cut_point_mm = Eigen::Vector3d::Zero();
  Eigen::Vector3d cut_normal = Eigen::Vector3d::UnitZ();
  int triangles = 0;                   // exactly this many (even); at least 2 nu nv
};

struct TopCap {
  Eigen::MatrixXd V;  // the cap's own new vertices (mm), numbered after the side's
  Eigen::MatrixXi F;  // indices into [side vertices, new vertices]; facing along cut_normal
};

// Throws EngineError when `triangles` is below the plain grid's 2 nu nv or odd.
TopCap top_cap(const TopCapInput& input);

}  // namespace lastcut
