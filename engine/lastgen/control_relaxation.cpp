#include "engine/lastgen/control_relaxation.hpp"

#include <Eigen/Geometry>

namespace lastcut {

void relax_control_cells(QuadMesh& control, const QuadTopology& topology, const RelaxationSurface& surface, int steps) {
  const auto vertex_count = static_cast<size_t>(control.vertex_count());
  // Boundary neighbours: the other ends of the boundary half-edges at each vertex.
  std::vector<std::vector<int>> rim_neighbours(vertex_count);
  for (int q = 0; q < control.quad_count(); ++q) {
    for (int k = 0; k < 4; ++k) {
      if (topology.twin[static_cast<size_t>(4 * q + k)] >= 0) continue;
      const int a = control.Q(q, k), b = control.Q(q, (k + 1) % 4);
      rim_neighbours[static_cast<size_t>(a)].push_back(b);
      rim_neighbours[static_cast<size_t>(b)].push_back(a);
    }
  }
  Eigen::MatrixXd weighted(control.V.rows(), 3);
  Eigen::VectorXd weight(control.V.rows());
  for (int step = 0; step < steps; ++step) {
    weighted.setZero();
    weight.setZero();
    for (int q = 0; q < control.quad_count(); ++q) {
      const Eigen::Vector3d p0 = control.V.row(control.Q(q, 0)), p1 = control.V.row(control.Q(q, 1)),
                            p2 = control.V.row(control.Q(q, 2)), p3 = control.V.row(control.Q(q, 3));
      const double area = 0.5 * (p2 - p0).cross(p3 - p1).norm();
      const Eigen::Vector3d centre = 0.25 * (p0 + p1 + p2 + p3);
      for (int k = 0; k < 4; ++k) {
        weighted.row(control.Q(q, k)) += area * centre.transpose();
        weight(control.Q(q, k)) += area;
      }
    }
    Eigen::MatrixXd moved = control.V;
    for (Eigen::Index v = 0; v < control.V.rows(); ++v) {
      const Eigen::Vector3d p = control.V.row(v);
      const std::vector<int>& rim = rim_neighbours[static_cast<size_t>(v)];
      if (topology.on_boundary[static_cast<size_t>(v)] != 0) {
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        for (int u : rim) mean += control.V.row(u).transpose();
        if (!rim.empty()) moved.row(v) = surface.onto_rim(0.5 * (p + mean / static_cast<double>(rim.size()))).transpose();
        continue;
      }
      if (!(weight(v) > 0.0)) continue;
      Eigen::Vector3d move = weighted.row(v).transpose() / weight(v) - p;
      const Eigen::Vector3d normal = surface.normal(p);
      move -= move.dot(normal) * normal;
      moved.row(v) = surface.project(p + move).transpose();
    }
    control.V = moved;
  }
}

}  // namespace lastcut
