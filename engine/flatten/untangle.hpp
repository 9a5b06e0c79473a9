#pragma once
// Local repair of flipped triangles in a flattening: the vertices around each flipped triangle are moved
// to the average of their neighbours (Gauss-Seidel sweeps of the uniform Laplacian, i.e. a local Tutte
// embedding of the region with its outline held), growing the region ring by ring until nothing is
// flipped. Only a few vertices move, so ARAP can polish the result with flip-guarded steps afterwards.
#include <Eigen/Core>

#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/disk_topology.hpp"

namespace lastcut {

struct UntangleReport {
  int flipped_before = 0;
  int flipped_after = 0;
  int rings = 0;           // region radius (in vertex rings) that was needed
  int moved_vertices = 0;  // vertices in the final region
};

// UV #V x 2, mm, changed in place. Tries up to max_rings rings around the flipped triangles.
UntangleReport untangle_flips(const TriangleFrames& frames, const DiskTopology& topology, Eigen::MatrixXd& UV,
                              int max_rings = 12);

}  // namespace lastcut
