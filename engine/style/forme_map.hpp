#pragma once
// A map from one half's forme (its flattening) onto the same half of another last: the correspondence a
// style is transferred through (issue 34, point 2).
//
// Method: cross-parameterisation through a common base domain (V. Kraevoy, A. Sheffer,
// "Cross-parameterization and compatible remeshing of 3D models", SIGGRAPH 2004; J. Schreiner et al.,
// "Inter-surface mapping", SIGGRAPH 2004), here with the simplest domain a half of an upper offers: each
// half is a disk whose outline the segmentation already splits at toe, heel, top_back and top_front.
//   1. The outline corresponds edge by edge at equal shares of 3D arc length (forme_boundary.hpp), so
//      the feather line goes to the feather line, the top edge to the top edge, landmarks to landmarks.
//   2. Inside, the map is harmonic with respect to the reference forme: each coordinate minimises the
//      Dirichlet energy with cotangent weights (U. Pinkall, K. Polthier 1993) on the reference's
//      flattening, with the outline fixed (a harmonic map, M. Eck et al., "Multiresolution analysis of
//      arbitrary meshes", SIGGRAPH 1995). Cotangent weights reproduce affine maps exactly, so a last
//      that is the reference scaled or moved maps without distortion; between two lasts the formes
//      differ smoothly and so does the map.
// Both halves must be flattenings of the same half (medial to medial); the map's orientation follows
// the formes' (a left and a right last's medial formes are mirror images, the map mirrors too).
#include <Eigen/Core>

#include "engine/style/forme_boundary.hpp"

namespace lastcut {

// One flattened half as the map reads it: 3D mesh (canonical frame, mm), its topology, its flattening
// UV (#V x 2, mm) and the four landmarks. The references must outlive the map's use.
struct FlatHalf {
  const TriMesh& mesh3d;
  const MeshTopology& topology;
  const Eigen::MatrixXd& UV;
  const std::map<std::string, int>& landmarks;
};

struct FormeMap {
  Eigen::MatrixXd target_uv;      // #V of the reference x 2: where each reference vertex lands in the target's UV
  FormeBoundary reference_outline, target_outline;
  int folded_triangles = 0;       // reference triangles whose image has the opposite orientation of most
};

// Throws EngineError (one line) when either half's outline cannot be split at its landmarks or the
// reference's flattening has a degenerate triangle.
FormeMap map_forme(const FlatHalf& reference, const FlatHalf& target);

}  // namespace lastcut
