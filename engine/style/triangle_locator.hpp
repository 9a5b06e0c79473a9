#pragma once
// Where a point lies on a triangle mesh: the closest point of the mesh to a query point, as a face and
// barycentric coordinates. Used in 3D (a point of a style line on a last's surface) and in 2D (a point of
// a flattened forme inside its triangles, where the closest point of a covering triangle is the point itself).
//
// Search: a bounding-volume hierarchy over the faces' boxes, Eigen's KdBVH with BVMinimize
// (unsupported/Eigen/BVH, libeigen3-dev), so a query visits a few boxes instead of every face.
// Closest point on one triangle: the Voronoi-region test of C. Ericson, "Real-Time Collision Detection"
// (Morgan Kaufmann 2005), section 5.1.5, written with dot products only, so it serves 2D and 3D alike.
#include <Eigen/Core>
#include <memory>

namespace lastcut {

struct SurfaceHit {
  int face = -1;                                       // index into F
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();  // weights of F(face, 0..2), >= 0, sum 1
  double distance_mm = 0;                              // from the query to the closest point
};

template <int Dim>
class TriangleLocator {
 public:
  using Point = Eigen::Matrix<double, Dim, 1>;
  // V: #V x Dim (mm), F: #F x 3. Both are copied; F must not be empty.
  TriangleLocator(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);
  ~TriangleLocator();
  TriangleLocator(TriangleLocator&&) noexcept;
  TriangleLocator& operator=(TriangleLocator&&) noexcept;

  // The closest point of the mesh to `query`; ties go to the lower face index.
  SurfaceHit closest(const Point& query) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

using SurfaceLocator = TriangleLocator<3>;
using FlatLocator = TriangleLocator<2>;

// The closest point to p on the triangle (a, b, c), as barycentric weights of a, b, c.
template <int Dim>
Eigen::Vector3d closest_on_triangle(const Eigen::Matrix<double, Dim, 1>& p, const Eigen::Matrix<double, Dim, 1>& a,
                                    const Eigen::Matrix<double, Dim, 1>& b, const Eigen::Matrix<double, Dim, 1>& c);

}  // namespace lastcut
