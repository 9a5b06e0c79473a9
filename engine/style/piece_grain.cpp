// A piece's grain line; see piece_grain.hpp.
#include "engine/style/piece_grain.hpp"

#include <algorithm>
#include <cmath>
#include <Eigen/Eigenvalues>
#include <numbers>
#include <vector>


namespace lastcut {
namespace {

constexpr double kExtentShare = 0.6;
constexpr double kLongest_mm = 120;
constexpr int kLinesAcross = 40;
constexpr double kWeakAxisShare = 0.5;  // the mapped axes' sum against their lengths' sum  // lines tried across the piece

// The direction of a polygon's largest extent (principal axis of its points), unit.
Point2 longest_extent(const Polygon2& polygon) {
  Point2 mean = Point2::Zero();
  for (const Point2& p : polygon.points) mean += p;
  mean /= static_cast<double>(polygon.points.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const Point2& p : polygon.points) scatter += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(scatter);
  return solver.eigenvectors().col(1).normalized();  // eigenvalues ascending
}

// The heel-to-toe axis as the flattening maps it, summed over the triangles by area (mm^2 x mm/mm), and
// the sum of the summands' lengths.
std::pair<Point2, double> mapped_heel_to_toe(const TriMesh& mesh, const Eigen::MatrixXd& UV) {
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  Point2 sum = Point2::Zero();
  double sum_of_lengths = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d p0 = mesh.V.row(mesh.F(f, 0)).transpose();
    const Eigen::Vector3d e1 = mesh.V.row(mesh.F(f, 1)).transpose() - p0, e2 = mesh.V.row(mesh.F(f, 2)).transpose() - p0;
    const Eigen::Vector3d normal = e1.cross(e2);
    const double twice_area = normal.norm();
    if (twice_area <= 0) continue;
    // The axis in the triangle's plane as a combination a e1 + b e2, and the same combination of the
    // flattened edges: the triangle's affine map applied to it.
    const Eigen::Vector3d in_plane = axis - axis.dot(normal) / (twice_area * twice_area) * normal;
    Eigen::Matrix2d gram;
    gram << e1.dot(e1), e1.dot(e2), e1.dot(e2), e2.dot(e2);
    const Eigen::Vector2d ab = gram.ldlt().solve(Eigen::Vector2d(e1.dot(in_plane), e2.dot(in_plane)));
    const Point2 u0 = UV.row(mesh.F(f, 0)).transpose();
    const Point2 mapped = ab.x() * (Point2(UV.row(mesh.F(f, 1)).transpose()) - u0) + ab.y() * (Point2(UV.row(mesh.F(f, 2)).transpose()) - u0);
    sum += 0.5 * twice_area * mapped;
    sum_of_lengths += 0.5 * twice_area * mapped.norm();
  }
  return {sum, sum_of_lengths};
}

}  // namespace

GrainLine piece_grain_line(const PieceSurface& surface, const PieceMold& mold, double grain_deg) {
  const auto [sum, sum_of_lengths] = mapped_heel_to_toe(surface.mesh, mold.UV);
  Point2 axis = sum.norm() > 0 ? Point2(sum.normalized()) : Point2(1, 0);
  // A piece round the heel (a counter) meets the axis going one way on each side: the mapped directions
  // cancel, and the piece's own length is the better reference.
  if (sum.norm() < kWeakAxisShare * sum_of_lengths) {
    const Point2 longest = longest_extent(mold.mold.net);
    axis = longest.dot(axis) < 0 ? Point2(-longest) : longest;
  }
  const double turn = grain_deg * std::numbers::pi / 180;
  const Point2 direction(std::cos(turn) * axis.x() - std::sin(turn) * axis.y(), std::sin(turn) * axis.x() + std::cos(turn) * axis.y());
  // The longest stretch of a line along `direction` inside the net, among lines across the whole piece:
  // the grain line lies in its middle (a counter's area centroid lies outside it).
  const Polygon2& net = mold.mold.net;
  const Point2 across(-direction.y(), direction.x());
  double low = INFINITY, high = -INFINITY;
  for (const Point2& p : net.points) low = std::min(low, p.dot(across)), high = std::max(high, p.dot(across));
  Point2 best_from = Point2::Zero(), best_to = Point2::Zero();
  for (int k = 1; k < kLinesAcross; ++k) {
    const Point2 origin = (low + (high - low) * k / kLinesAcross) * across;
    std::vector<double> crossings;  // along direction from origin
    for (std::size_t i = 0; i < net.points.size(); ++i) {
      const Point2 a = net.points[i], b = net.points[(i + 1) % net.points.size()];
      const double da = (a - origin).dot(across), db = (b - origin).dot(across);
      if ((da > 0) == (db > 0)) continue;
      const Point2 at = a + (b - a) * (da / (da - db));
      crossings.push_back((at - origin).dot(direction));
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t i = 0; i + 1 < crossings.size(); i += 2)
      if (crossings[i + 1] - crossings[i] > (best_to - best_from).norm())
        best_from = origin + crossings[i] * direction, best_to = origin + crossings[i + 1] * direction;
  }
  const Point2 centre = 0.5 * (best_from + best_to);
  const double half_mm = std::min(kExtentShare * (best_to - best_from).norm(), kLongest_mm) / 2;
  return {centre - half_mm * direction, centre + half_mm * direction};
}

}  // namespace lastcut
