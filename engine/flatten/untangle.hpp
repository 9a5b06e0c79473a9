#pragma once
// Local repair of flipped triangles in a flattening: the vertices within a few rings of the flipped
// triangles are re-placed by a Tutte embedding of that region (each vertex the average of its neighbours,
// solved exactly by sparse Cholesky) with the region's outer ring held, doubling the radius until nothing
// is flipped. W. T. Tutte, "How to draw a graph", Proc. London Math. Soc. 13, 1963: when the held ring is
// convex the region is guaranteed flip-free; around a small fold it is close enough to convex in practice.
// If that fails (a fold reaching the outline), Gauss-Seidel averaging grown ring by ring, with outline
// vertices sliding between their boundary neighbours, is tried. Only the region moves, so ARAP can
// polish it with flip-guarded steps afterwards.
#include <Eigen/Core>

#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/disk_topology.hpp"

namespace lastcut {

struct UntangleReport {
  int flipped_before = 0;
  int flipped_after = 0;
  int rings = 0;           // region radius (in vertex rings) that was needed
  int moved_vertices = 0;  // vertices re-placed in the final region
};

// UV #V x 2, mm, changed in place (left unchanged if no region up to max_rings removes every flip).
// The first strategy holds the outline; the second may move outline vertices inside the region.
UntangleReport untangle_flips(const TriangleFrames& frames, const DiskTopology& topology, Eigen::MatrixXd& UV,
                              int max_rings = 64);

}  // namespace lastcut
