#include "engine/style/forme_map.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/flatten/cotangent_laplacian.hpp"

namespace lastcut {
namespace {

// Where each reference outline vertex goes: the target outline point at the same share of the same edge.
Eigen::MatrixXd outline_targets(const FormeMap& map, const FlatHalf& target, Eigen::Index reference_vertices,
                                std::vector<char>& fixed) {
  Eigen::MatrixXd targets = Eigen::MatrixXd::Zero(reference_vertices, 2);
  fixed.assign(static_cast<std::size_t>(reference_vertices), 0);
  for (const FormeEdge& edge : map.reference_outline.edges) {
    const FormeEdge& onto = map.target_outline.edge(edge.kind);
    for (std::size_t i = 0; i < edge.vertices.size(); ++i) {
      const EdgeSpot spot = spot_at_share(onto, edge.share[i]);
      targets.row(edge.vertices[i]) = (1 - spot.weight_b) * target.UV.row(spot.a) + spot.weight_b * target.UV.row(spot.b);
      fixed[static_cast<std::size_t>(edge.vertices[i])] = 1;
    }
  }
  return targets;
}

double signed_area(const Eigen::MatrixXd& P, const Eigen::MatrixXi& F, Eigen::Index f) {
  const Eigen::RowVector2d a = P.row(F(f, 0)), b = P.row(F(f, 1)), c = P.row(F(f, 2));
  return 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
}

}  // namespace

FormeMap map_forme(const FlatHalf& reference, const FlatHalf& target) {
  FormeMap map;
  map.reference_outline = forme_boundary(reference.mesh3d, reference.topology, reference.landmarks);
  map.target_outline = forme_boundary(target.mesh3d, target.topology, target.landmarks);
  const Eigen::Index n = reference.UV.rows();
  std::vector<char> fixed;
  map.target_uv = outline_targets(map, target, n, fixed);

  // Dirichlet energy on the reference forme: the flattening as a planar mesh gives its cotangent weights.
  TriMesh forme;
  forme.V = Eigen::MatrixXd::Zero(n, 3);
  forme.V.leftCols(2) = reference.UV;
  forme.F = reference.mesh3d.F;
  const TriangleFrames frames = compute_triangle_frames(forme);
  std::vector<int> row(static_cast<std::size_t>(n), -1);
  int unknowns = 0;
  for (Eigen::Index v = 0; v < n; ++v)
    if (!fixed[static_cast<std::size_t>(v)]) row[static_cast<std::size_t>(v)] = unknowns++;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, 2);
  for (std::size_t f = 0; f < frames.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int i = frames.triangles[f][static_cast<std::size_t>((k + 1) % 3)];
      const int j = frames.triangles[f][static_cast<std::size_t>((k + 2) % 3)];
      const double w = frames.half_weight[3 * f + static_cast<std::size_t>(k)];
      for (const auto& [a, b] : {std::pair{i, j}, std::pair{j, i}}) {
        const int ra = row[static_cast<std::size_t>(a)];
        if (ra < 0) continue;
        entries.emplace_back(ra, ra, w);
        const int rb = row[static_cast<std::size_t>(b)];
        if (rb >= 0)
          entries.emplace_back(ra, rb, -w);
        else
          rhs.row(ra) += w * map.target_uv.row(b);
      }
    }
  if (unknowns > 0) {
    Eigen::SparseMatrix<double> laplacian(unknowns, unknowns);
    laplacian.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
    if (solver.info() != Eigen::Success) throw EngineError("the forme map's system could not be factored");
    const Eigen::MatrixXd inside = solver.solve(rhs);
    for (Eigen::Index v = 0; v < n; ++v)
      if (row[static_cast<std::size_t>(v)] >= 0) map.target_uv.row(v) = inside.row(row[static_cast<std::size_t>(v)]);
  }

  // Orientation of the map: most triangles keep (or, between mirror-image formes, all reverse) their turn.
  int same = 0, reversed = 0;
  for (Eigen::Index f = 0; f < reference.mesh3d.F.rows(); ++f) {
    const double before = signed_area(reference.UV, reference.mesh3d.F, f);
    const double after = signed_area(map.target_uv, reference.mesh3d.F, f);
    if (before * after > 0) ++same;
    else ++reversed;
  }
  map.folded_triangles = std::min(same, reversed);
  return map;
}

}  // namespace lastcut
