#pragma once
// Pairwise clustering (Elkeran, "A new approach for sheet nesting problem using guided cuckoo search
// and pairwise clustering", European Journal of Operational Research 231, 2013): two pieces that
// together almost fill a rectangle (two right triangles making a square, a notch and the piece that
// fills it) are nested as one piece and split again in the layout. Local search rarely finds such
// exact complements on its own: it needs both pieces in the right rotations at the same spot at once.
// A pair qualifies when, with the first piece in its own frame and the second in one of its allowed
// rotations with one of its vertices on a vertex of the first, the two do not overlap (touching is
// allowed: the pair is cut with zero kerf), their union is one simple polygon, and it fills at least
// 95 % of its bounding box and 5 points more than either piece fills its own (pair_clusters.cpp).
// Pairs are merged best fill first; the search still moves and rotates each pair as a whole.
// Only pieces of at most 64 vertices with an explicit rotation list that includes 0, no mirroring
// and no grain take part, and only when the gap between pieces is zero (a kerf would have to be
// opened inside the pair).
#include <map>
#include <vector>

#include "engine/nest/layout.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

struct ClusterMember {
  int item_id = 0;
  double rotation_deg = 0;         // in the cluster's frame, counter-clockwise
  Point2 offset = Point2::Zero();  // in the cluster's frame, mm
};

struct PairClusters {
  NestInstance instance;                                  // the items to nest: clusters plus what is left over
  std::map<int, std::vector<ClusterMember>> members;      // by cluster item id
};

// The instance with the best-filling pairs merged (greedily, best fill first, as many copies as both
// demands allow). Without qualifying pairs the instance comes back unchanged (members empty).
// gap_mm: the kerf between pieces (no clusters unless 0); margin_mm: from the strip's edges (a pair
// must fit the strip's height in one of its rotations).
PairClusters cluster_pairs(const NestInstance& instance, double gap_mm, double margin_mm);

// The layout of the clustered instance as a layout of the original one: every cluster placement
// becomes its members' placements; unplaced clusters are listed as their members. Utilisation is
// recomputed on `original`.
Layout expand_clusters(const Layout& clustered, const PairClusters& clusters, const NestInstance& original);

}  // namespace lastcut
