#include "tests/subdiv/quad_test_meshes.hpp"

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace lastcut::test {

QuadMesh cube_sphere(int m, double radius_mm) {
  std::map<std::array<int, 3>, int> ids;
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector4i> quads;
  const auto id_of = [&](std::array<int, 3> lattice) {
    const auto [it, inserted] = ids.emplace(lattice, static_cast<int>(positions.size()));
    if (inserted) {
      Eigen::Vector3d p(lattice[0], lattice[1], lattice[2]);
      p = (2.0 * p / m - Eigen::Vector3d::Ones()).normalized();
      // A smooth wobble so that no symmetry hides an indexing error.
      const double wobble = 1.0 + 0.12 * std::sin(2.0 * p.x() + 1.0) * std::cos(3.0 * p.y()) + 0.05 * p.z() * p.z();
      positions.push_back(radius_mm * wobble * p);
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    for (int side : {0, m}) {
      for (int j = 0; j < m; ++j) {
        for (int i = 0; i < m; ++i) {
          std::array<int, 4> corner_ids{};
          const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            std::array<int, 3> lattice{};
            lattice[static_cast<size_t>(axis)] = side;
            lattice[static_cast<size_t>(b)] = i + di[k];
            lattice[static_cast<size_t>(c)] = j + dj[k];
            corner_ids[static_cast<size_t>(k)] = id_of(lattice);
          }
          if (side == m) {
            quads.emplace_back(corner_ids[0], corner_ids[1], corner_ids[2], corner_ids[3]);
          } else {
            quads.emplace_back(corner_ids[0], corner_ids[3], corner_ids[2], corner_ids[1]);
          }
        }
      }
    }
  }
  QuadMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(positions.size()), 3);
  for (size_t v = 0; v < positions.size(); ++v) mesh.V.row(static_cast<Eigen::Index>(v)) = positions[v].transpose();
  mesh.Q.resize(static_cast<Eigen::Index>(quads.size()), 4);
  for (size_t q = 0; q < quads.size(); ++q) mesh.Q.row(static_cast<Eigen::Index>(q)) = quads[q].transpose();
  return mesh;
}

QuadMesh height_grid(int nx, int ny, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
  double a[3][3];
  for (auto& row : a) {
    for (double& value : row) value = coefficient(random);
  }
  QuadMesh mesh;
  mesh.V.resize((nx + 1) * (ny + 1), 3);
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      double z = 0.0;
      for (int p = 0; p < 3; ++p) {
        for (int q = 0; q < 3; ++q) z += a[p][q] * std::cos(0.4 * p * i + 0.3) * std::sin(0.35 * q * j + 0.7);
      }
      mesh.V.row(i + (nx + 1) * j) << i, j, 2.0 * z;
    }
  }
  mesh.Q.resize(nx * ny, 4);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int v = i + (nx + 1) * j;
      mesh.Q.row(i + nx * j) << v, v + 1, v + 1 + (nx + 1), v + (nx + 1);
    }
  }
  return mesh;
}

bool face_is_regular(const QuadMesh& mesh, int q) {
  std::vector<std::set<int>> neighbours(static_cast<size_t>(mesh.vertex_count()));
  for (int f = 0; f < mesh.quad_count(); ++f) {
    for (int k = 0; k < 4; ++k) {
      neighbours[static_cast<size_t>(mesh.Q(f, k))].insert(mesh.Q(f, (k + 1) % 4));
      neighbours[static_cast<size_t>(mesh.Q(f, (k + 1) % 4))].insert(mesh.Q(f, k));
    }
  }
  for (int k = 0; k < 4; ++k) {
    if (neighbours[static_cast<size_t>(mesh.Q(q, k))].size() != 4) return false;
  }
  return true;
}

}  // namespace lastcut::test
