#include "engine/style/triangle_locator.hpp"

#include <unsupported/Eigen/BVH>

#include <limits>
#include <vector>

#include "engine/core/engine_error.hpp"

namespace lastcut {

template <int Dim>
Eigen::Vector3d closest_on_triangle(const Eigen::Matrix<double, Dim, 1>& p, const Eigen::Matrix<double, Dim, 1>& a,
                                    const Eigen::Matrix<double, Dim, 1>& b, const Eigen::Matrix<double, Dim, 1>& c) {
  const Eigen::Matrix<double, Dim, 1> ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};  // vertex region a
  const Eigen::Matrix<double, Dim, 1> bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};  // vertex region b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {  // edge region ab
    const double t = d1 / (d1 - d3);
    return {1 - t, t, 0};
  }
  const Eigen::Matrix<double, Dim, 1> cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};  // vertex region c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {  // edge region ac
    const double t = d2 / (d2 - d6);
    return {1 - t, 0, t};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {  // edge region bc
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - t, t};
  }
  const double sum = va + vb + vc;
  if (!(sum > 0)) return {1, 0, 0};  // a degenerate triangle: its first corner stands for it
  return {va / sum, vb / sum, vc / sum};
}

template Eigen::Vector3d closest_on_triangle<2>(const Eigen::Vector2d&, const Eigen::Vector2d&, const Eigen::Vector2d&,
                                                const Eigen::Vector2d&);
template Eigen::Vector3d closest_on_triangle<3>(const Eigen::Vector3d&, const Eigen::Vector3d&, const Eigen::Vector3d&,
                                                const Eigen::Vector3d&);

template <int Dim>
struct TriangleLocator<Dim>::Tree {
  using Box = Eigen::AlignedBox<double, Dim>;
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  Eigen::KdBVH<double, Dim, int> hierarchy;

  Point corner(int face, int k) const { return V.row(F(face, k)).transpose(); }
};

namespace {

// BVMinimize's visitor: the smallest distance to any face seen so far, and where it was.
template <int Dim, typename Tree>
struct ClosestFace {
  using Scalar = double;
  using Point = Eigen::Matrix<double, Dim, 1>;
  const Tree& tree;
  Point query;
  SurfaceHit best;

  double minimumOnVolume(const Eigen::AlignedBox<double, Dim>& box) const { return std::sqrt(box.squaredExteriorDistance(query)); }
  double minimumOnObject(int face) {
    const Point a = tree.corner(face, 0), b = tree.corner(face, 1), c = tree.corner(face, 2);
    const Eigen::Vector3d weights = closest_on_triangle<Dim>(query, a, b, c);
    const double distance = (weights(0) * a + weights(1) * b + weights(2) * c - query).norm();
    if (distance < best.distance_mm || (distance == best.distance_mm && face < best.face)) {
      best.face = face;
      best.barycentric = weights;
      best.distance_mm = distance;
    }
    return distance;
  }
};

}  // namespace

template <int Dim>
TriangleLocator<Dim>::TriangleLocator(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) : tree_(std::make_unique<Tree>()) {
  if (F.rows() == 0) throw EngineError("no triangles to locate points on");
  if (V.cols() != Dim) throw EngineError("point locator: vertices have the wrong dimension");
  tree_->V = V;
  tree_->F = F;
  std::vector<int> faces(static_cast<std::size_t>(F.rows()));
  std::vector<typename Tree::Box> boxes(faces.size());
  for (int f = 0; f < F.rows(); ++f) {
    faces[static_cast<std::size_t>(f)] = f;
    typename Tree::Box& box = boxes[static_cast<std::size_t>(f)];
    for (int k = 0; k < 3; ++k) box.extend(tree_->corner(f, k));
  }
  tree_->hierarchy.init(faces.begin(), faces.end(), boxes.begin(), boxes.end());
}

template <int Dim>
TriangleLocator<Dim>::~TriangleLocator() = default;
template <int Dim>
TriangleLocator<Dim>::TriangleLocator(TriangleLocator&&) noexcept = default;
template <int Dim>
TriangleLocator<Dim>& TriangleLocator<Dim>::operator=(TriangleLocator&&) noexcept = default;

template <int Dim>
SurfaceHit TriangleLocator<Dim>::closest(const Point& query) const {
  ClosestFace<Dim, Tree> visitor{*tree_, query, {}};
  visitor.best.distance_mm = std::numeric_limits<double>::infinity();
  Eigen::BVMinimize(tree_->hierarchy, visitor);
  return visitor.best;
}

template class TriangleLocator<2>;
template class TriangleLocator<3>;

}  // namespace lastcut
