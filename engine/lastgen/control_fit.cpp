#include "engine/lastgen/control_fit.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/subdiv/bezier_patches.hpp"

namespace lastcut {
namespace {

struct Sample {
  int face = 0;
  double u = 0.0, v = 0.0;
  bool on_rim = false;
};

std::array<double, 4> bernstein(double t) {
  const double s = 1.0 - t;
  return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}

// Corner k of a face at these parameters.
constexpr double kCornerUv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

std::vector<Sample> samples_of(const QuadMesh& control, const QuadTopology& topology, int s) {
  std::vector<Sample> samples;
  // Every control vertex's limit point once, evaluated on its first face.
  for (int v = 0; v < control.vertex_count(); ++v) {
    if (topology.faces_at(v) == 0) continue;
    const int h = topology.half_edge_at(v, 0);
    samples.push_back({h / 4, kCornerUv[h % 4][0], kCornerUv[h % 4][1], topology.on_boundary[static_cast<size_t>(v)] != 0});
  }
  for (int q = 0; q < control.quad_count(); ++q) {
    for (int j = 0; j < s; ++j) {
      for (int i = 0; i < s; ++i) samples.push_back({q, (i + 0.5) / s, (j + 0.5) / s, false});
    }
    // Along boundary edges: the rim curve between its control vertices.
    for (int k = 0; k < 4; ++k) {
      if (topology.twin[static_cast<size_t>(4 * q + k)] >= 0) continue;
      for (int i = 0; i < s; ++i) {
        const double t = (i + 0.5) / s;
        const Eigen::Vector2d a(kCornerUv[k][0], kCornerUv[k][1]), b(kCornerUv[(k + 1) % 4][0], kCornerUv[(k + 1) % 4][1]);
        const Eigen::Vector2d uv = (1 - t) * a + t * b;
        samples.push_back({q, uv.x(), uv.y(), true});
      }
    }
  }
  return samples;
}

}  // namespace

void fit_control_least_squares(QuadMesh& control, const QuadTopology& topology, const ControlFitTargets& targets,
                               const ControlFitOptions& options) {
  const std::vector<Sample> samples = samples_of(control, topology, options.samples_per_edge);
  const std::vector<PatchWeights> weights = bezier_patch_weights(control, topology);
  const auto rows = static_cast<Eigen::Index>(samples.size());
  const Eigen::Index unknowns = control.V.rows();

  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index r = 0; r < rows; ++r) {
    const Sample& sample = samples[static_cast<size_t>(r)];
    const std::array<double, 4> bu = bernstein(sample.u), bv = bernstein(sample.v);
    const PatchWeights& net = weights[static_cast<size_t>(sample.face)];
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) {
        const double basis = bu[static_cast<size_t>(i)] * bv[static_cast<size_t>(j)];
        if (basis == 0.0) continue;
        for (const auto& [vertex, w] : net.b[static_cast<size_t>(i + 4 * j)]) entries.emplace_back(static_cast<int>(r), vertex, basis * w);
      }
    }
  }
  Eigen::SparseMatrix<double> A(rows, unknowns);
  A.setFromTriplets(entries.begin(), entries.end());

  // Umbrella Laplacian of the control net; boundary vertices along the boundary only.
  std::vector<std::vector<int>> neighbours(static_cast<size_t>(unknowns));
  for (int q = 0; q < control.quad_count(); ++q) {
    for (int k = 0; k < 4; ++k) {
      const int h = 4 * q + k;
      const int a = control.Q(q, k), b = control.Q(q, (k + 1) % 4);
      const bool boundary_edge = topology.twin[static_cast<size_t>(h)] < 0;
      // Each inner edge appears twice (once per direction); count it from its lower half-edge only.
      if (!boundary_edge && topology.edge_half_edge[static_cast<size_t>(topology.edge_of[static_cast<size_t>(h)])] != h) continue;
      for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
        if (topology.on_boundary[static_cast<size_t>(from)] != 0 && !boundary_edge) continue;
        neighbours[static_cast<size_t>(from)].push_back(to);
      }
    }
  }
  entries.clear();
  for (Eigen::Index v = 0; v < unknowns; ++v) {
    const std::vector<int>& ring = neighbours[static_cast<size_t>(v)];
    if (ring.empty()) continue;
    entries.emplace_back(static_cast<int>(v), static_cast<int>(v), 1.0);
    for (int u : ring) entries.emplace_back(static_cast<int>(v), u, -1.0 / static_cast<double>(ring.size()));
  }
  Eigen::SparseMatrix<double> L(unknowns, unknowns);
  L.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> fairness = options.fairness * Eigen::SparseMatrix<double>(L.transpose() * L);

  Eigen::VectorXd sample_weight = Eigen::VectorXd::Zero(rows);
  Eigen::MatrixXd position(rows, 3), target(rows, 3);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    const std::vector<BezierPatch> patches = build_bezier_patches(control, topology);
    bool changed = false;
    for (Eigen::Index r = 0; r < rows; ++r) {
      const Sample& sample = samples[static_cast<size_t>(r)];
      const Eigen::Vector3d p = patch_position(patches[static_cast<size_t>(sample.face)], sample.u, sample.v);
      const Eigen::Vector3d foot = sample.on_rim ? targets.onto_rim(p) : targets.onto_surface(p);
      position.row(r) = p.transpose();
      target.row(r) = foot.transpose();
      // Weights only grow (a sample once held harder stays so): the factor is rebuilt only when a
      // sample newly needs holding, and the iteration cannot flip a sample back and forth.
      const double weight = targets.weight(p, foot);
      if (weight > sample_weight(r)) {
        changed = true;
        sample_weight(r) = weight;
      }
    }
    if (changed) {
      const Eigen::SparseMatrix<double> normal =
          Eigen::SparseMatrix<double>(A.transpose() * sample_weight.asDiagonal() * A) + fairness;
      solver.compute(normal);
      if (solver.info() != Eigen::Success) throw EngineError("control fit: a control vertex has no samples");
    }
    // Gauss-Newton step: the exact residual, the linear model's (approximate at extraordinary vertices) Jacobian.
    const Eigen::MatrixXd rhs = A.transpose() * (sample_weight.asDiagonal() * (target - position)) - fairness * control.V;
    control.V += solver.solve(rhs);
  }
}

}  // namespace lastcut
