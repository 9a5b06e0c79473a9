#include "engine/lastgen/top_cap.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

constexpr int kSmoothingSteps = 50;

// 4 sqrt(3) area / (sum of squared edges): 1 for an equilateral triangle, 0 for a degenerate one.
double triangle_quality(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double edges = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  return edges > 0.0 ? 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / edges : 0.0;
}

// Triangles of the finer layout: inner grid, transition row, and the rim's own 2 (nu + nv) + ring.
long long fine_count(int nu, int nv, int Nu, int Nv) {
  return 2LL * (Nu - 2) * (Nv - 2) + 2LL * (nu + nv) + 2LL * (Nu - 2 + Nv - 2);
}

// A grid of (Nu + 1) x (Nv + 1) points inside the border `border(i, j)` (called for border points only):
// the Coons patch of the border, smoothed. Row-major, i fastest.
std::vector<Eigen::Vector3d> coons_grid(int Nu, int Nv, const std::function<Eigen::Vector3d(int, int)>& border) {
  std::vector<Eigen::Vector3d> p(static_cast<size_t>((Nu + 1) * (Nv + 1)));
  const auto at = [&p, Nu](int i, int j) -> Eigen::Vector3d& { return p[static_cast<size_t>(i + (Nu + 1) * j)]; };
  for (int i = 0; i <= Nu; ++i) at(i, 0) = border(i, 0), at(i, Nv) = border(i, Nv);
  for (int j = 1; j < Nv; ++j) at(0, j) = border(0, j), at(Nu, j) = border(Nu, j);
  for (int j = 1; j < Nv; ++j) {
    for (int i = 1; i < Nu; ++i) {
      const double u = static_cast<double>(i) / Nu, v = static_cast<double>(j) / Nv;
      at(i, j) = (1 - v) * at(i, 0) + v * at(i, Nv) + (1 - u) * at(0, j) + u * at(Nu, j) -
                 ((1 - u) * (1 - v) * at(0, 0) + u * (1 - v) * at(Nu, 0) + (1 - u) * v * at(0, Nv) + u * v * at(Nu, Nv));
    }
  }
  for (int step = 0; step < kSmoothingSteps; ++step) {
    const std::vector<Eigen::Vector3d> previous = p;
    const auto was = [&previous, Nu](int i, int j) { return previous[static_cast<size_t>(i + (Nu + 1) * j)]; };
    for (int j = 1; j < Nv; ++j)
      for (int i = 1; i < Nu; ++i) at(i, j) = 0.25 * (was(i - 1, j) + was(i + 1, j) + was(i, j - 1) + was(i, j + 1));
  }
  return p;
}

// Collects vertices and triangles; quads split along the diagonal whose worse triangle is the better
// one (near the grid's corners the rim can squeeze a cell either way), or into four around their centre.
struct CapBuilder {
  const Eigen::MatrixXd& side;
  std::vector<Eigen::Vector3d> added;
  std::vector<Eigen::Vector3i> faces;

  int add(const Eigen::Vector3d& p) {
    added.push_back(p);
    return static_cast<int>(side.rows()) + static_cast<int>(added.size()) - 1;
  }
  Eigen::Vector3d at(int id) const {
    return id < side.rows() ? Eigen::Vector3d(side.row(id).transpose()) : added[static_cast<size_t>(id - side.rows())];
  }
  // Corners q0 .. q3 as the old grid ran them: g(i, j), g(i, j + 1), g(i + 1, j + 1), g(i + 1, j).
  void quad(const std::array<int, 4>& q, bool split_in_four) {
    if (split_in_four) {
      const int centre = add(0.25 * (at(q[0]) + at(q[1]) + at(q[2]) + at(q[3])));
      for (size_t k = 0; k < 4; ++k) faces.emplace_back(q[k], q[(k + 1) % 4], centre);
      return;
    }
    const auto quality = [&](size_t a, size_t b, size_t c) { return triangle_quality(at(q[a]), at(q[b]), at(q[c])); };
    if (std::min(quality(0, 1, 2), quality(0, 2, 3)) >= std::min(quality(0, 1, 3), quality(1, 2, 3))) {
      faces.emplace_back(q[0], q[1], q[2]);
      faces.emplace_back(q[0], q[2], q[3]);
    } else {
      faces.emplace_back(q[0], q[1], q[3]);
      faces.emplace_back(q[1], q[2], q[3]);
    }
  }
};

// Which of `cells` quads to split: `splits` of them spread evenly.
std::vector<char> spread_splits(int cells, long long splits) {
  std::vector<char> split(static_cast<size_t>(cells), 0);
  for (long long s = 0; s < splits; ++s) split[static_cast<size_t>((2 * s + 1) * cells / (2 * splits))] = 1;
  return split;
}

}  // namespace

TopCap top_cap(const TopCapInput& in) {
  const Eigen::MatrixXd& V = *in.V;
  const int nu = in.nu, nv = in.nv;
  const auto loop_size = static_cast<int>(in.loop.size());
  if (loop_size != 2 * (nu + nv) || nu < 1 || nv < 1) throw EngineError("top cap: the rim loop does not match its arcs");
  if (in.triangles % 2 != 0 || in.triangles < 2 * nu * nv) throw EngineError("top cap: too few triangles for the rim's grid");
  const auto rim = [&](double index) -> Eigen::Vector3d {  // fractional position along the loop
    const double wrapped = std::fmod(index + loop_size, static_cast<double>(loop_size));
    const int k = std::min(static_cast<int>(wrapped), loop_size - 1);
    const double w = wrapped - k;
    return (1 - w) * V.row(in.loop[static_cast<size_t>(k)]).transpose() + w * V.row(in.loop[static_cast<size_t>((k + 1) % loop_size)]).transpose();
  };
  double length_u = 0.0, length_v = 0.0;
  for (int k = 0; k < loop_size; ++k) {
    const double edge = (rim(k + 1) - rim(k)).norm();
    ((k < nu || (k >= nu + nv && k < 2 * nu + nv)) ? length_u : length_v) += 0.5 * edge;
  }

  // The finer layout with the most triangles not above the count, cells near square.
  int Nu = 0, Nv = 0;
  const double spacing = std::sqrt(2.0 * length_u * length_v / in.triangles);
  for (int u = std::max(3, static_cast<int>(std::lround(length_u / spacing))); u >= 3 && Nv == 0; --u) {
    int v = 3;
    if (fine_count(nu, nv, u, v) > in.triangles) continue;
    while (fine_count(nu, nv, u, v + 1) <= in.triangles) ++v;
    Nu = u, Nv = v;
  }
  CapBuilder cap{V, {}, {}};
  const auto into_cut = [&in](const Eigen::Vector3d& p) -> Eigen::Vector3d {
    return p - (p - in.cut_point_mm).dot(in.cut_normal) * in.cut_normal;
  };

  if (Nu == 0 || static_cast<long long>(Nu) * Nv <= static_cast<long long>(nu) * nv) {
    // The rim's own grid: its border is the rim samples.
    const auto border = [&](int i, int j) {
      return j == 0 ? rim(i) : i == nu ? rim(nu + j) : j == nv ? rim(2 * nu + nv - i) : rim(loop_size - j);
    };
    const std::vector<Eigen::Vector3d> p = coons_grid(nu, nv, border);
    std::vector<int> id(p.size());
    for (int j = 0; j <= nv; ++j) {
      for (int i = 0; i <= nu; ++i) {
        const auto k = static_cast<size_t>(i + (nu + 1) * j);
        if (j == 0) id[k] = in.loop[static_cast<size_t>(i)];
        else if (i == nu) id[k] = in.loop[static_cast<size_t>(nu + j)];
        else if (j == nv) id[k] = in.loop[static_cast<size_t>(2 * nu + nv - i)];
        else if (i == 0) id[k] = in.loop[static_cast<size_t>((loop_size - j) % loop_size)];
        else id[k] = cap.add(into_cut(p[k]));
      }
    }
    const long long splits = (in.triangles - 2LL * nu * nv) / 2;
    // Spread over the cells off the rim (the squarest), over all cells if too few.
    std::vector<int> candidates;
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i)
        if (i > 0 && i < nu - 1 && j > 0 && j < nv - 1) candidates.push_back(i + nu * j);
    if (static_cast<long long>(candidates.size()) < splits) {
      candidates.clear();
      for (int c = 0; c < nu * nv; ++c) candidates.push_back(c);
    }
    if (static_cast<long long>(candidates.size()) < splits) throw EngineError("top cap: the triangle count is too far from the rim's grid");
    const std::vector<char> chosen = spread_splits(static_cast<int>(candidates.size()), splits);
    std::vector<char> split(static_cast<size_t>(nu * nv), 0);
    for (size_t c = 0; c < candidates.size(); ++c) split[static_cast<size_t>(candidates[c])] = chosen[c];
    const auto g = [&](int i, int j) { return id[static_cast<size_t>(i + (nu + 1) * j)]; };
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) cap.quad({g(i, j), g(i, j + 1), g(i + 1, j + 1), g(i + 1, j)}, split[static_cast<size_t>(i + nu * j)] != 0);
  } else {
    // The finer grid, its border on the rim polygon at evenly spread fractional loop positions.
    const double su = static_cast<double>(nu) / Nu, sv = static_cast<double>(nv) / Nv;
    const auto border = [&](int i, int j) {
      return j == 0 ? rim(su * i) : i == Nu ? rim(nu + sv * j) : j == Nv ? rim(2 * nu + nv - su * i) : rim(loop_size - sv * j);
    };
    const std::vector<Eigen::Vector3d> p = coons_grid(Nu, Nv, border);
    std::vector<int> id(p.size(), -1);
    for (int j = 1; j < Nv; ++j)
      for (int i = 1; i < Nu; ++i) id[static_cast<size_t>(i + (Nu + 1) * j)] = cap.add(into_cut(p[static_cast<size_t>(i + (Nu + 1) * j)]));
    const auto g = [&](int i, int j) { return id[static_cast<size_t>(i + (Nu + 1) * j)]; };
    const int inner = (Nu - 2) * (Nv - 2);
    const std::vector<char> split = spread_splits(inner, (in.triangles - fine_count(nu, nv, Nu, Nv)) / 2);
    for (int j = 1; j < Nv - 1; ++j)
      for (int i = 1; i < Nu - 1; ++i)
        cap.quad({g(i, j), g(i, j + 1), g(i + 1, j + 1), g(i + 1, j)}, split[static_cast<size_t>((i - 1) + (Nu - 2) * (j - 1))] != 0);

    // The transition row: rim loop A and the inner grid's outer ring B, both from the (0, 0) corner on.
    std::vector<int> ring;
    for (int i = 1; i < Nu - 1; ++i) ring.push_back(g(i, 1));
    for (int j = 1; j < Nv - 1; ++j) ring.push_back(g(Nu - 1, j));
    for (int i = Nu - 1; i > 1; --i) ring.push_back(g(i, Nv - 1));
    for (int j = Nv - 1; j > 1; --j) ring.push_back(g(1, j));
    const auto& A = in.loop;
    const auto m = A.size(), k = ring.size();
    size_t a = 0, b = 0;
    while (a < m || b < k) {
      bool advance_a = b == k;
      if (a < m && b < k) {
        advance_a = (cap.at(A[(a + 1) % m]) - cap.at(ring[b % k])).squaredNorm() <
                    (cap.at(A[a % m]) - cap.at(ring[(b + 1) % k])).squaredNorm();
      }
      if (advance_a) {
        cap.faces.emplace_back(A[(a + 1) % m], A[a % m], ring[b % k]);
        ++a;
      } else {
        cap.faces.emplace_back(ring[b % k], ring[(b + 1) % k], A[a % m]);
        ++b;
      }
    }
  }
  if (static_cast<int>(cap.faces.size()) != in.triangles) throw EngineError("top cap: the triangle count does not add up");
  TopCap result;
  result.V.resize(static_cast<Eigen::Index>(cap.added.size()), 3);
  for (size_t v = 0; v < cap.added.size(); ++v) result.V.row(static_cast<Eigen::Index>(v)) = cap.added[v].transpose();
  result.F.resize(static_cast<Eigen::Index>(cap.faces.size()), 3);
  for (size_t f = 0; f < cap.faces.size(); ++f) result.F.row(static_cast<Eigen::Index>(f)) = cap.faces[f].transpose();
  return result;
}

}  // namespace lastcut
