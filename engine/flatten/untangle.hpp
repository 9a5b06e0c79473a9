#pragma once
// Local repair of flipped triangles in a flattening, most local first:
//  1. vertex by vertex into the kernel of its star, a few rings at most (star_untangle.hpp);
//  2. the vertices within a few rings of the flipped triangles re-placed by a convex-combination embedding
//     of that region with its outer ring held (clamped cotangent weights, then Tutte's uniform ones),
//     doubling the radius until nothing is flipped. W. T. Tutte, "How to draw a graph", Proc. London Math.
//     Soc. 13, 1963: flip-free when the held ring is convex; measured on the FIND halves, the region's
//     outer ring is concave enough that new folds appear next to it, which is why (1) comes first;
//  3. Gauss-Seidel averaging grown ring by ring, with outline vertices sliding between their boundary
//     neighbours.
// Only the region moves, so ARAP can polish it with flip-guarded steps afterwards.
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
UntangleReport untangle_flips(const TriangleFrames& frames, const MeshTopology& topology, Eigen::MatrixXd& UV,
                              int max_rings = 64);

}  // namespace lastcut
