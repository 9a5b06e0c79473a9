// ARAP with held edge lengths; see arap_held_lengths.hpp.
#include "engine/flatten/arap_held_lengths.hpp"

#include <algorithm>
#include <cmath>

#include "engine/flatten/arap_local_step.hpp"
#include "engine/flatten/cotangent_laplacian.hpp"

namespace lastcut {
namespace {

constexpr int kMaxHalvings = 10;  // a step cut to 1/1024 that still folds a triangle ends the run

struct HeldSpring {
  int from = 0, to = 0;  // vertex ids
  double length_mm = 0;  // on the last
  double weight = 0;     // s in the energy (hpp)
};

// The spring's best target for the current map: its 3D length along (u_to - u_from) (any direction
// where the map has collapsed the edge to a point: never seen, but one is needed).
Eigen::Vector2d spring_target(const HeldSpring& spring, const Eigen::MatrixXd& UV) {
  const Eigen::Vector2d along = (UV.row(spring.to) - UV.row(spring.from)).transpose();
  const double norm = along.norm();
  return norm > 1e-12 ? Eigen::Vector2d(along * (spring.length_mm / norm)) : Eigen::Vector2d(spring.length_mm, 0.0);
}

// A vertex on no held edge, for the global step to pin (the energy is translation invariant, so any
// vertex pinned at its current place gives the same minimiser; one off the springs keeps their rows simple).
int free_vertex(const std::vector<HeldSpring>& springs, Eigen::Index vertex_count) {
  std::vector<char> on_spring(static_cast<std::size_t>(vertex_count), 0);
  for (const HeldSpring& spring : springs) on_spring[spring.from] = on_spring[spring.to] = 1;
  const auto it = std::find(on_spring.begin(), on_spring.end(), 0);
  return it == on_spring.end() ? 0 : static_cast<int>(it - on_spring.begin());
}

bool no_new_flips(const std::vector<char>& before, const std::vector<char>& after) {
  for (std::size_t f = 0; f < before.size(); ++f)
    if (after[f] == kFlipped && before[f] != kFlipped) return false;
  return true;
}

}  // namespace

HeldLengthReport hold_edge_lengths(const TriMesh& mesh, const MeshTopology& topology, const std::vector<std::array<int, 2>>& held,
                                   Eigen::MatrixXd& UV, const HeldLengthOptions& options) {
  HeldLengthReport report;
  if (held.empty()) return report;
  std::vector<HeldSpring> springs;
  for (const auto& [from, to] : held) springs.push_back({from, to, (mesh.V.row(to) - mesh.V.row(from)).norm(), 0});

  const TriangleFrames frames = compute_triangle_frames(mesh);
  ReducedLaplacian laplacian = build_reduced_pattern(frames, topology, free_vertex(springs, mesh.V.rows()));
  std::vector<char> fixed(static_cast<std::size_t>(mesh.V.rows()), 0);
  fixed[static_cast<std::size_t>(laplacian.pinned)] = 1;  // its entries have no slot in the reduced pattern
  assemble_laplacian(frames, frames.half_weight, fixed, laplacian);
  // The springs' part of the matrix: s on both diagonals, -s between (entries of mesh edges, in the
  // pattern). s is the weight times the stiffness the cotangent weights give the edge's ends (at least
  // 1): next to a sliver of the cut those are thousands, and a plain weight would not hold the edge.
  for (HeldSpring& spring : springs) {
    const int a = laplacian.row_of_vertex[spring.from], b = laplacian.row_of_vertex[spring.to];
    spring.weight = options.weight * std::max(1.0, 0.5 * (laplacian.matrix.coeff(a, a) + laplacian.matrix.coeff(b, b)));
  }
  for (const HeldSpring& spring : springs) {
    const int a = laplacian.row_of_vertex[spring.from], b = laplacian.row_of_vertex[spring.to];
    laplacian.matrix.coeffRef(a, a) += spring.weight;
    laplacian.matrix.coeffRef(b, b) += spring.weight;
    laplacian.matrix.coeffRef(a, b) -= spring.weight;
    laplacian.matrix.coeffRef(b, a) -= spring.weight;
  }
  SparseCholesky factor(options.solver);
  factor.analyze_pattern(laplacian.matrix);
  factor.factorize(laplacian.matrix);

  const ArapLocalStep local(frames, laplacian);
  std::vector<double> rhs;
  Eigen::MatrixXd reduced_rhs, next;
  const auto energy_and_rhs = [&](const Eigen::MatrixXd& map) {
    double energy = local.run(map, rhs);
    for (const HeldSpring& spring : springs) {
      const Eigen::Vector2d target = spring_target(spring, map);
      const Eigen::Vector2d along = (map.row(spring.to) - map.row(spring.from)).transpose();
      energy += spring.weight * (along - target).squaredNorm();
      for (int c = 0; c < 2; ++c) {
        rhs[2 * static_cast<std::size_t>(spring.to) + c] += spring.weight * target[c];
        rhs[2 * static_cast<std::size_t>(spring.from) + c] -= spring.weight * target[c];
      }
    }
    return energy;
  };
  double energy = energy_and_rhs(UV);
  report.energy_start = energy;
  std::vector<char> state, next_state;
  classify_triangles(frames, UV, state);
  for (report.iterations = 0; report.iterations < options.max_iterations;) {
    local.reduce(rhs, UV, reduced_rhs);
    local.expand(factor.solve(reduced_rhs), UV, next);
    // The flip guard of arap_iterations.hpp, against flips only: a step that would flip a triangle is
    // halved (E is convex in u for fixed rotations and targets, so a shorter step still lowers it). A
    // cut piece keeps slivers along its outline whose area any step changes by a large share; guarding
    // them against collapse too (to 5 % of their 3D area) stalled the hold on most derby vamps.
    int halvings = 0;
    for (classify_triangles(frames, next, next_state); !no_new_flips(state, next_state) && halvings < kMaxHalvings;
         classify_triangles(frames, next, next_state)) {
      next = 0.5 * (UV + next);
      ++halvings;
    }
    if (halvings == kMaxHalvings) {
      report.stalled_on_flips = true;
      break;
    }
    report.shortened_steps += halvings > 0;
    ++report.iterations;
    state.swap(next_state);
    const double next_energy = energy_and_rhs(next);
    UV.swap(next);
    const bool settled = energy - next_energy <= options.relative_energy_tolerance * energy;
    energy = next_energy;
    if (settled) {
      report.converged = true;
      break;
    }
  }
  report.energy_final = energy;
  return report;
}

}  // namespace lastcut
