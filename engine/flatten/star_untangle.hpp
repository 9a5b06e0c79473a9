#pragma once
// Untangling a flattening by moving single vertices into the kernel of their star.
//
// The triangles around vertex v (its star) are all positively oriented exactly when v lies left of every
// directed link edge (a, b) of its incident triangles (v, a, b): inside the kernel of its link polygon,
// an intersection of half-planes. Each sweep moves every vertex of the active set, one at a time
// (Gauss-Seidel), to the point of that intersection farthest from its lines: the Chebyshev centre, a
// 3-variable linear program solved exactly by enumerating its vertices. When the kernel is empty the same
// point still maximises the worst signed distance, so no star gets worse. The active set starts with the
// vertices of the flipped triangles and grows one ring whenever a few sweeps did not remove every flip.
// Local optimisation-based untangling in the sense of L. A. Freitag, P. Plassmann, "Local
// optimization-based simplicial mesh untangling and improvement", Int. J. Numer. Meth. Engng 49, 2000.
// Only a few rings move, so the rest of the ARAP map is kept exactly.
#include <Eigen/Core>

#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/disk_topology.hpp"

namespace lastcut {

struct StarUntangleReport {
  int flipped_before = 0;
  int flipped_after = 0;
  int sweeps = 0;          // Gauss-Seidel sweeps done
  int rings = 0;           // rings around the flipped triangles' vertices that were allowed to move
  int moved_vertices = 0;  // size of the final active set
};

// UV #V x 2, mm, changed in place; on failure (flips left after max_sweeps) it keeps the partly untangled
// map only if it has fewer flipped triangles than before, else it is restored.
StarUntangleReport star_untangle(const TriangleFrames& frames, const MeshTopology& topology, Eigen::MatrixXd& UV,
                                 int max_rings = 8, int max_sweeps = 200);

}  // namespace lastcut
