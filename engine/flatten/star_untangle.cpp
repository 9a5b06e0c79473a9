// Vertex-by-vertex untangling into the kernel of each star; see star_untangle.hpp.
#include "engine/flatten/star_untangle.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace lastcut {
namespace {

// Sweeps without removing every flip before the active set grows by one ring.
constexpr int kSweepsPerRing = 8;

// A half-plane n . p >= c with |n| = 1.
struct HalfPlane {
  double nx, ny, c;
};

// Chebyshev centre of the half-planes: the p maximising min_k (n_k . p - c_k), found among the vertices
// of the 3-variable LP (every triple of constraints). `best_margin` is that minimum (< 0: empty kernel).
// The caller bounds the region with a box so the LP is bounded.
bool chebyshev_centre(const std::vector<HalfPlane>& planes, Eigen::Vector2d& best, double& best_margin) {
  const size_t m = planes.size();
  bool found = false;
  best_margin = -1e300;
  for (size_t i = 0; i < m; ++i) {
    for (size_t j = i + 1; j < m; ++j) {
      for (size_t k = j + 1; k < m; ++k) {
        // n . p - t = c for the three planes.
        Eigen::Matrix3d A;
        A << planes[i].nx, planes[i].ny, -1.0, planes[j].nx, planes[j].ny, -1.0, planes[k].nx, planes[k].ny, -1.0;
        const double det = A.determinant();
        if (std::abs(det) < 1e-12) continue;
        const Eigen::Vector3d x = A.inverse() * Eigen::Vector3d(planes[i].c, planes[j].c, planes[k].c);
        if (x.z() <= best_margin) continue;
        bool feasible = true;
        for (const HalfPlane& h : planes) {
          if (h.nx * x.x() + h.ny * x.y() - h.c < x.z() - 1e-12) {
            feasible = false;
            break;
          }
        }
        if (!feasible) continue;
        best = x.head<2>();
        best_margin = x.z();
        found = true;
      }
    }
  }
  return found;
}

double twice_area(const Eigen::MatrixXd& UV, const std::array<int, 3>& t) {
  const double ax = UV(t[1], 0) - UV(t[0], 0), ay = UV(t[1], 1) - UV(t[0], 1);
  const double bx = UV(t[2], 0) - UV(t[0], 0), by = UV(t[2], 1) - UV(t[0], 1);
  return ax * by - ay * bx;
}

int count_flips(const TriangleFrames& frames, const std::vector<int>& faces, const Eigen::MatrixXd& UV) {
  int flips = 0;
  for (int f : faces) flips += twice_area(UV, frames.triangles[f]) <= 0.0 ? 1 : 0;
  return flips;
}

}  // namespace

StarUntangleReport star_untangle(const TriangleFrames& frames, const MeshTopology& topology, Eigen::MatrixXd& UV,
                                 int max_rings, int max_sweeps) {
  StarUntangleReport report;
  const int vertex_count = static_cast<int>(UV.rows());
  const int face_count = static_cast<int>(frames.triangles.size());
  std::vector<int> flipped;
  for (int f = 0; f < face_count; ++f) {
    if (twice_area(UV, frames.triangles[f]) <= 0.0) flipped.push_back(f);
  }
  report.flipped_before = report.flipped_after = static_cast<int>(flipped.size());
  if (flipped.empty()) return report;

  // Incident triangles of every vertex (compressed rows).
  std::vector<int> star_offsets(vertex_count + 1, 0), stars(3 * static_cast<size_t>(face_count));
  for (const auto& t : frames.triangles) {
    for (int v : t) ++star_offsets[v + 1];
  }
  for (int v = 0; v < vertex_count; ++v) star_offsets[v + 1] += star_offsets[v];
  {
    std::vector<int> next(star_offsets.begin(), star_offsets.end() - 1);
    for (int f = 0; f < face_count; ++f) {
      for (int v : frames.triangles[f]) stars[next[v]++] = f;
    }
  }

  // Only the region's vertices move and every flipped triangle has one, so the flips can only change
  // among the triangles around the region: those are the ones counted after each sweep.
  std::vector<char> active(vertex_count, 0), touched(face_count, 0);
  std::vector<int> region, region_faces;
  const auto add_to_region = [&](int v) {
    if (active[v]) return;
    active[v] = 1;
    region.push_back(v);
    for (int s = star_offsets[v]; s < star_offsets[v + 1]; ++s) {
      if (!touched[stars[s]]) {
        touched[stars[s]] = 1;
        region_faces.push_back(stars[s]);
      }
    }
  };
  for (int f : flipped) {
    for (int v : frames.triangles[f]) add_to_region(v);
  }
  const Eigen::MatrixXd original = UV;
  std::vector<HalfPlane> planes;
  int flips = report.flipped_before;
  for (int sweep = 0; sweep < max_sweeps && flips > 0; ++sweep) {
    if (sweep > 0 && sweep % kSweepsPerRing == 0 && report.rings < max_rings) {
      const size_t inner = region.size();
      for (size_t i = 0; i < inner; ++i) {
        for (int k = topology.neighbor_offsets[region[i]]; k < topology.neighbor_offsets[region[i] + 1]; ++k) {
          add_to_region(topology.neighbors[k]);
        }
      }
      ++report.rings;
    }
    for (int v : region) {
      planes.clear();
      double reach = 0.0;  // longest link edge: the box keeps the LP bounded without limiting real moves
      for (int s = star_offsets[v]; s < star_offsets[v + 1]; ++s) {
        const auto& t = frames.triangles[stars[s]];
        const int at = t[0] == v ? 0 : t[1] == v ? 1 : 2;
        const int a = t[(at + 1) % 3], b = t[(at + 2) % 3];
        const double ex = UV(b, 0) - UV(a, 0), ey = UV(b, 1) - UV(a, 1);
        const double length = std::hypot(ex, ey);
        if (length <= 0.0) continue;
        reach = std::max(reach, length);
        const double nx = -ey / length, ny = ex / length;
        planes.push_back({nx, ny, nx * UV(a, 0) + ny * UV(a, 1)});
      }
      if (planes.empty()) continue;
      const double x = UV(v, 0), y = UV(v, 1);
      planes.push_back({1.0, 0.0, x - reach});
      planes.push_back({-1.0, 0.0, -x - reach});
      planes.push_back({0.0, 1.0, y - reach});
      planes.push_back({0.0, -1.0, -y - reach});
      Eigen::Vector2d centre;
      double margin = 0.0;
      if (chebyshev_centre(planes, centre, margin)) UV.row(v) = centre.transpose();
    }
    report.sweeps = sweep + 1;
    flips = count_flips(frames, region_faces, UV);
  }
  report.moved_vertices = static_cast<int>(region.size());
  report.flipped_after = flips;
  if (flips >= report.flipped_before) {
    UV = original;
    report.flipped_after = report.flipped_before;
  }
  return report;
}

}  // namespace lastcut
