#include "engine/style/piece_formes.hpp"

#include <optional>

#include "engine/core/engine_error.hpp"
#include "engine/mold/clipper_paths.hpp"
#include "engine/style/triangle_locator.hpp"

namespace lastcut {
namespace {

// A point of a half's surface carried into its flattening by the barycentric weights of its closest point.
Point2 forme_point(const SegmentResult& half, const SurfaceHit& hit) {
  Point2 uv = Point2::Zero();
  for (int k = 0; k < 3; ++k) uv += hit.barycentric(k) * half.UV.row(half.mesh3d.F(hit.face, k)).transpose();
  return uv;
}

}  // namespace

std::vector<PieceForme> piece_formes(const std::array<const SegmentResult*, 2>& halves,
                                     const std::vector<StylePieceResult>& pieces) {
  const std::array<SurfaceLocator, 2> locators = {SurfaceLocator(halves[0]->mesh3d.V, halves[0]->mesh3d.F),
                                                  SurfaceLocator(halves[1]->mesh3d.V, halves[1]->mesh3d.F)};
  std::vector<PieceForme> formes;
  for (const StylePieceResult& piece : pieces) {
    const TriMesh& mesh = piece.surface.mesh;
    // A corner on the centre seam is carried into both flattenings, each by its own half.
    std::array<std::vector<std::optional<Point2>>, 2> carried;
    for (auto& half_points : carried) half_points.resize(static_cast<std::size_t>(mesh.V.rows()));
    std::array<ClipperLib::Paths, 2> triangles;
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
      const Eigen::Vector3d centroid = (mesh.V.row(mesh.F(f, 0)) + mesh.V.row(mesh.F(f, 1)) + mesh.V.row(mesh.F(f, 2))).transpose() / 3;
      const std::array<SurfaceHit, 2> hits = {locators[0].closest(centroid), locators[1].closest(centroid)};
      const std::size_t h = hits[1].distance_mm < hits[0].distance_mm ? 1 : 0;
      if (hits[h].distance_mm > kPieceOffHalves_mm)
        throw EngineError("piece " + piece.spec.name + " has a triangle on neither half of the last");
      std::vector<Point2> corners;
      for (int k = 0; k < 3; ++k) {
        std::optional<Point2>& uv = carried[h][static_cast<std::size_t>(mesh.F(f, k))];
        if (!uv) uv = forme_point(*halves[h], locators[h].closest(mesh.V.row(mesh.F(f, k)).transpose()));
        corners.push_back(*uv);
      }
      ClipperLib::Path path = to_clipper_path(corners);
      if (!ClipperLib::Orientation(path)) ClipperLib::ReversePath(path);  // one winding, so non-zero fill adds them up
      triangles[h].push_back(std::move(path));
    }
    PieceForme forme{piece.spec.name, {}};
    for (std::size_t h = 0; h < 2; ++h) {
      if (triangles[h].empty()) continue;
      ClipperLib::Clipper clipper;
      clipper.AddPaths(triangles[h], ClipperLib::ptSubject, true);
      clipper.Execute(ClipperLib::ctUnion, forme.rings[h], ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    }
    formes.push_back(std::move(forme));
  }
  return formes;
}

}  // namespace lastcut
