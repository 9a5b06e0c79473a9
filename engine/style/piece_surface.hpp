#pragma once
// A piece's 3D surface cut from the new last (issue 34, point 3, "flattening by the 3D contour"): the
// triangles of each half that lie in the piece's region (upper_regions.hpp), clipped exactly to it in
// the half's flattening and lifted back to 3D by their barycentric coordinates, the parts on the two
// halves joined along the centre seam. The piece is then flattened on its own.
//
// Clipping: Clipper (libpolyclipping) intersects a triangle with the region only where a region edge
// passes through the triangle's box (a grid of the region's edges tells which); the others lie wholly
// inside or outside and are kept or dropped by their centroid. Clipped polygons are triangulated by ear
// clipping (H. Meisters, "Polygons have ears", Amer. Math. Monthly 82, 1975: every simple polygon with
// more than three corners has two ears to cut off). Vertices are welded: the same cut point computed
// from the two triangles of an edge (within kSameWeld_mm), and a piece's seam vertices on both halves
// (within kSeamWeld_mm: where a line crosses the seam, its strip meets the seam a few micrometres apart
// in the two flattenings). Edges under kShortestEdge_mm, crumbs of a cut passing next to a vertex of the
// last, are collapsed (engine/mesh/short_edge_collapse.hpp).
#include <array>
#include <string>

#include "engine/core/tri_mesh.hpp"
#include "engine/style/upper_regions.hpp"

namespace lastcut {

inline constexpr double kSameWeld_mm = 1e-4;
inline constexpr double kSeamWeld_mm = 0.05;
// Far below the outline's simplification tolerance (0.02 mm, piece_mold.hpp) and any knife's accuracy.
inline constexpr double kShortestEdge_mm = 0.05;

struct PieceSurface {
  std::string name;
  TriMesh mesh;            // canonical frame of the new last, mm, outward like the last
  double area_mm2 = 0;
  int clipped_triangles = 0;  // triangles of the halves cut by the piece's outline
};

// halves: the new last's medial and lateral halves (the ones piece_regions was given); seam_cuts: the
// cut stretches of the seams (the ones piece_regions was given): the piece's parts on the two halves are
// one only where it is sewn across a seam (seam_welds.hpp).
PieceSurface cut_piece_surface(const std::array<const SegmentResult*, 2>& halves, const PieceRegion& piece,
                               const std::vector<SeamCut>& seam_cuts = {});

}  // namespace lastcut
