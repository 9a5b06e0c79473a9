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

QuadMesh pentagon_prism(double radius_mm) {
  // Ids: top ring 0-4, top midpoints 5-9, bottom ring 10-14, bottom midpoints 15-19, top centre 20, bottom centre 21.
  QuadMesh mesh;
  mesh.V.resize(22, 3);
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < 5; ++i) {
    for (int level = 0; level < 2; ++level) {
      const double z = level == 0 ? 0.6 : -0.6;
      const double corner = 2.0 * pi * i / 5.0, middle = corner + pi / 5.0;
      mesh.V.row(i + 10 * level) = Eigen::RowVector3d(std::cos(corner), std::sin(corner), z).normalized() * radius_mm;
      mesh.V.row(5 + i + 10 * level) = Eigen::RowVector3d(std::cos(middle), std::sin(middle), z).normalized() * radius_mm * 1.05;
    }
  }
  mesh.V.row(20) << 0, 0, radius_mm;
  mesh.V.row(21) << 0, 0, -radius_mm;
  mesh.Q.resize(20, 4);
  for (int i = 0; i < 5; ++i) {
    const int next = (i + 1) % 5, before = (i + 4) % 5;
    mesh.Q.row(4 * i) << 20, 5 + before, i, 5 + i;                       // top cap, counter-clockwise from above
    mesh.Q.row(4 * i + 1) << 21, 15 + i, 10 + i, 15 + before;             // bottom cap, reversed
    mesh.Q.row(4 * i + 2) << 10 + i, 15 + i, 5 + i, i;                    // side, seen from outside
    mesh.Q.row(4 * i + 3) << 15 + i, 10 + next, next, 5 + i;
  }
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
