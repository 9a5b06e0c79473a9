#include "engine/segment/level_set_cut.hpp"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace lastcut {
namespace {

int sign_of(double value) { return value > 0.0 ? 1 : (value < 0.0 ? -1 : 0); }

}  // namespace

void snap_to_zero_level(const Eigen::MatrixXi& F, Eigen::Ref<Eigen::VectorXd> values, double snap_fraction) {
  // Crossings very close to a vertex move onto the vertex; all decided from the values before snapping.
  std::vector<char> snap(static_cast<std::size_t>(values.size()), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      const double fa = values(a), fb = values(b);
      if (sign_of(fa) * sign_of(fb) >= 0) continue;
      const double t = fa / (fa - fb);
      if (t < snap_fraction) snap[static_cast<std::size_t>(a)] = 1;
      if (t > 1.0 - snap_fraction) snap[static_cast<std::size_t>(b)] = 1;
    }
  for (std::size_t v = 0; v < snap.size(); ++v)
    if (snap[v]) values(static_cast<Eigen::Index>(v)) = 0.0;
}

void cut_along_zero_level(TriMesh& mesh, Eigen::MatrixXd& fields, int column, double snap_fraction) {
  const Eigen::Index face_count = mesh.F.rows();
  snap_to_zero_level(mesh.F, fields.col(column), snap_fraction);

  std::unordered_map<std::uint64_t, int> crossing_vertex;
  std::vector<Eigen::RowVector3d> new_positions;
  std::vector<Eigen::RowVectorXd> new_values;
  const Eigen::Index first_new = mesh.V.rows();
  auto crossing = [&](int a, int b) {
    const int lo = std::min(a, b), hi = std::max(a, b);
    const std::uint64_t key = (static_cast<std::uint64_t>(lo) << 32) | static_cast<std::uint32_t>(hi);
    auto [it, inserted] = crossing_vertex.emplace(key, 0);
    if (inserted) {
      const double t = fields(lo, column) / (fields(lo, column) - fields(hi, column));
      new_positions.push_back((1.0 - t) * mesh.V.row(lo) + t * mesh.V.row(hi));
      Eigen::RowVectorXd values = (1.0 - t) * fields.row(lo) + t * fields.row(hi);
      values(column) = 0.0;
      new_values.push_back(values);
      it->second = static_cast<int>(first_new + static_cast<Eigen::Index>(new_positions.size()) - 1);
    }
    return it->second;
  };

  std::vector<Eigen::RowVector3i> faces;
  faces.reserve(static_cast<std::size_t>(face_count) + 1024);
  std::vector<int> positive, negative;
  for (Eigen::Index f = 0; f < face_count; ++f) {
    const std::array<int, 3> corner{mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2)};
    std::array<int, 3> sign{};
    for (int k = 0; k < 3; ++k) sign[static_cast<std::size_t>(k)] = sign_of(fields(corner[static_cast<std::size_t>(k)], column));
    const bool crossed = sign[0] * sign[1] < 0 || sign[1] * sign[2] < 0 || sign[2] * sign[0] < 0;
    if (!crossed) {
      faces.emplace_back(corner[0], corner[1], corner[2]);
      continue;
    }
    positive.clear();
    negative.clear();
    for (std::size_t k = 0; k < 3; ++k) {
      const int v = corner[k], w = corner[(k + 1) % 3];
      if (sign[k] >= 0) positive.push_back(v);
      if (sign[k] <= 0) negative.push_back(v);
      if (sign[k] * sign[(k + 1) % 3] < 0) {
        const int x = crossing(v, w);
        positive.push_back(x);
        negative.push_back(x);
      }
    }
    auto position_of = [&](int v) -> Eigen::RowVector3d {
      return v < first_new ? Eigen::RowVector3d(mesh.V.row(v)) : new_positions[static_cast<std::size_t>(v - first_new)];
    };
    for (const std::vector<int>* piece : {&positive, &negative}) {
      if (piece->size() == 3) {
        faces.emplace_back((*piece)[0], (*piece)[1], (*piece)[2]);
      } else if (piece->size() == 4) {  // split the quad along its shorter diagonal
        const std::vector<int>& c = *piece;
        if ((position_of(c[0]) - position_of(c[2])).squaredNorm() <= (position_of(c[1]) - position_of(c[3])).squaredNorm()) {
          faces.emplace_back(c[0], c[1], c[2]);
          faces.emplace_back(c[0], c[2], c[3]);
        } else {
          faces.emplace_back(c[1], c[2], c[3]);
          faces.emplace_back(c[1], c[3], c[0]);
        }
      }
    }
  }
  const Eigen::Index total = first_new + static_cast<Eigen::Index>(new_positions.size());
  mesh.V.conservativeResize(total, 3);
  fields.conservativeResize(total, fields.cols());
  for (std::size_t i = 0; i < new_positions.size(); ++i) {
    mesh.V.row(first_new + static_cast<Eigen::Index>(i)) = new_positions[i];
    fields.row(first_new + static_cast<Eigen::Index>(i)) = new_values[i];
  }
  mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i) mesh.F.row(static_cast<Eigen::Index>(i)) = faces[i];
}

}  // namespace lastcut
