#include "engine/style/piece_surface.hpp"

#include <cmath>
#include <unordered_map>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/mesh/short_edge_collapse.hpp"
#include "engine/mold/clipper_paths.hpp"
#include "engine/style/seam_welds.hpp"

namespace lastcut {
namespace {

using ClipperLib::cInt;

constexpr cInt kCell = static_cast<cInt>(2.0 * kClipperUnitsPerMm);  // grid cell of the region's edges: 2 mm
constexpr double kOnOutline_mm = 1e-4;  // a clipped point this close to a triangle's outline edge lies on it
constexpr cInt kTile = static_cast<cInt>(16.0 * kClipperUnitsPerMm);  // the region is cut into tiles this size

struct Box {
  cInt x0, y0, x1, y1;
};

// Which region edges pass through which 2 mm cell.
class EdgeGrid {
 public:
  explicit EdgeGrid(const ClipperLib::Paths& rings) {
    for (const ClipperLib::Path& ring : rings)
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const ClipperLib::IntPoint a = ring[i], b = ring[(i + 1) % ring.size()];
        for (cInt cx = cell(std::min(a.X, b.X)); cx <= cell(std::max(a.X, b.X)); ++cx)
          for (cInt cy = cell(std::min(a.Y, b.Y)); cy <= cell(std::max(a.Y, b.Y)); ++cy) cells_[key(cx, cy)] = 1;
      }
  }
  // True when some region edge may pass through the box.
  bool touches(const Box& box) const {
    for (cInt cx = cell(box.x0); cx <= cell(box.x1); ++cx)
      for (cInt cy = cell(box.y0); cy <= cell(box.y1); ++cy)
        if (cells_.count(key(cx, cy))) return true;
    return false;
  }

 private:
  static cInt cell(cInt v) { return v >= 0 ? v / kCell : -((-v + kCell - 1) / kCell); }
  static std::uint64_t key(cInt cx, cInt cy) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(cx)) << 32) | static_cast<std::uint32_t>(cy);
  }
  std::unordered_map<std::uint64_t, char> cells_;
};

cInt floor_div(cInt v, cInt step) { return v >= 0 ? v / step : -((-v + step - 1) / step); }

// The region cut into square tiles, each computed when first needed: a triangle is clipped against the
// few region edges of the tiles under it, not against the whole outline.
class RegionTiles {
 public:
  explicit RegionTiles(const ClipperLib::Paths& rings) : rings_(rings) {}

  // The region within the tiles that cover the box.
  ClipperLib::Paths around(const Box& box) {
    const cInt tx0 = floor_div(box.x0, kTile), tx1 = floor_div(box.x1, kTile);
    const cInt ty0 = floor_div(box.y0, kTile), ty1 = floor_div(box.y1, kTile);
    if (tx0 == tx1 && ty0 == ty1) return tile(tx0, ty0);
    ClipperLib::Clipper joined;
    for (cInt tx = tx0; tx <= tx1; ++tx)
      for (cInt ty = ty0; ty <= ty1; ++ty) joined.AddPaths(tile(tx, ty), ClipperLib::ptSubject, true);
    ClipperLib::Paths local;
    joined.Execute(ClipperLib::ctUnion, local, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return local;
  }

 private:
  const ClipperLib::Paths& tile(cInt tx, cInt ty) {
    const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(tx)) << 32) | static_cast<std::uint32_t>(ty);
    const auto found = tiles_.find(key);
    if (found != tiles_.end()) return found->second;
    const ClipperLib::Path square = {{tx * kTile, ty * kTile}, {(tx + 1) * kTile, ty * kTile},
                                     {(tx + 1) * kTile, (ty + 1) * kTile}, {tx * kTile, (ty + 1) * kTile}};
    ClipperLib::Clipper clipper;
    clipper.AddPaths(rings_, ClipperLib::ptSubject, true);
    clipper.AddPath(square, ClipperLib::ptClip, true);
    ClipperLib::Paths local;
    clipper.Execute(ClipperLib::ctIntersection, local, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return tiles_.emplace(key, std::move(local)).first->second;
  }

  const ClipperLib::Paths& rings_;
  std::unordered_map<std::uint64_t, ClipperLib::Paths> tiles_;
};

bool inside_rings(const ClipperLib::Paths& rings, const ClipperLib::IntPoint& p) {
  if (ClipperLib::PointInPolygon(p, rings.front()) != 1) return false;
  for (std::size_t i = 1; i < rings.size(); ++i)
    if (ClipperLib::PointInPolygon(p, rings[i]) != 0) return false;
  return true;
}

double cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Ear clipping of a simple polygon (mm): triangles as index triples into `polygon`, counter-clockwise.
std::vector<std::array<int, 3>> ear_clip(const std::vector<Point2>& polygon) {
  std::vector<int> left(polygon.size());
  for (std::size_t i = 0; i < left.size(); ++i) left[i] = static_cast<int>(i);
  double area = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) area += cross(Point2::Zero(), polygon[i], polygon[(i + 1) % polygon.size()]);
  if (area < 0) std::reverse(left.begin(), left.end());
  std::vector<std::array<int, 3>> triangles;
  std::size_t guard = 0;
  while (left.size() > 3 && guard < 4 * polygon.size() * polygon.size()) {
    bool cut = false;
    for (std::size_t i = 0; i < left.size() && !cut; ++i, ++guard) {
      const int a = left[(i + left.size() - 1) % left.size()], b = left[i], c = left[(i + 1) % left.size()];
      const Point2 &pa = polygon[static_cast<std::size_t>(a)], &pb = polygon[static_cast<std::size_t>(b)],
                   &pc = polygon[static_cast<std::size_t>(c)];
      if (cross(pa, pb, pc) <= 0) continue;  // reflex or flat corner: not an ear
      bool empty = true;
      for (const int v : left) {
        if (v == a || v == b || v == c) continue;
        const Point2& p = polygon[static_cast<std::size_t>(v)];
        if (cross(pa, pb, p) >= 0 && cross(pb, pc, p) >= 0 && cross(pc, pa, p) >= 0) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      triangles.push_back({a, b, c});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
      cut = true;
    }
    if (!cut) break;  // only flat corners left: the rest has no area
  }
  if (left.size() == 3 && cross(polygon[static_cast<std::size_t>(left[0])], polygon[static_cast<std::size_t>(left[1])],
                                polygon[static_cast<std::size_t>(left[2])]) > 0)
    triangles.push_back({left[0], left[1], left[2]});
  return triangles;
}

// Vertices of the piece, welded: within one half's part only the same point computed twice (from the
// two triangles of an edge) is one vertex; across parts a point on its half's outline takes the nearest
// outline point of another part within kSeamWeld_mm that no point of its own part has taken yet (the
// split plane's cut leaves slivers along the seam, whose inner corners lie that close to the seam too). One to one: where a part's
// triangles are small (at the toe), two of its points near one point of the other part would otherwise
// both be welded to it and the triangle between them would vanish, leaving a hole. A wider weld inside
// a part would pinch a piece's narrow tip into a non-manifold vertex.
class WeldedVertices {
 public:
  // on_outline: p lies on its half's outline, the only place two halves' points can be one.
  int add(const Eigen::Vector3d& p, int part, bool on_outline) {
    const std::uint64_t own = part_bit(part);
    const std::array<long long, 3> c = cell(p);
    int other = -1;
    double other_mm = kSeamWeld_mm;
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto found = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (found == cells_.end()) continue;
          for (const int a : found->second) {
            const Alias& alias = aliases_[static_cast<std::size_t>(a)];
            const double distance = (alias.point - p).norm();
            if (alias.part == part && distance <= kSameWeld_mm) return alias.vertex;
            if (on_outline && alias.on_outline && alias.part != part && distance <= other_mm &&
                !(parts_of_[static_cast<std::size_t>(alias.vertex)] & own))
              other_mm = distance, other = alias.vertex;
          }
        }
    if (other < 0) {
      other = static_cast<int>(points_.size());
      points_.push_back(p);
      parts_of_.push_back(0);
    }
    parts_of_[static_cast<std::size_t>(other)] |= own;
    aliases_.push_back({p, part, other, on_outline});
    cells_[key(c)].push_back(static_cast<int>(aliases_.size()) - 1);
    return other;
  }
  const std::vector<Eigen::Vector3d>& points() const { return points_; }

 private:
  struct Alias {
    Eigen::Vector3d point;  // as this part computed it
    int part;
    int vertex;  // the welded vertex it stands for
    bool on_outline;
  };
  static std::uint64_t part_bit(int part) { return std::uint64_t{1} << (part % 64); }
  static std::array<long long, 3> cell(const Eigen::Vector3d& p) {
    return {std::llround(std::floor(p.x() / kSeamWeld_mm)), std::llround(std::floor(p.y() / kSeamWeld_mm)),
            std::llround(std::floor(p.z() / kSeamWeld_mm))};
  }
  static std::uint64_t key(const std::array<long long, 3>& c) {
    return (static_cast<std::uint64_t>(c[0] & 0x1fffff) << 42) | (static_cast<std::uint64_t>(c[1] & 0x1fffff) << 21) |
           static_cast<std::uint64_t>(c[2] & 0x1fffff);
  }
  std::vector<Eigen::Vector3d> points_;
  std::vector<std::uint64_t> parts_of_;  // per vertex: the parts whose points are welded to it
  std::vector<Alias> aliases_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

}  // namespace

PieceSurface cut_piece_surface(const std::array<const SegmentResult*, 2>& halves, const PieceRegion& piece,
                               const std::vector<SeamCut>& seam_cuts) {
  PieceSurface surface;
  surface.name = piece.name;
  WeldedVertices vertices;
  const SeamWelds welds(halves, piece, seam_cuts);
  // A point on its half's outline may be one with the other half's only where the piece is sewn across the seam.
  const auto weldable = [&](const Eigen::Vector3d& p, bool on_outline) { return on_outline && welds.weldable(p); };
  std::vector<std::array<int, 3>> faces;
  for (std::size_t part_index_size = 0; part_index_size < piece.parts.size(); ++part_index_size) {
    const HalfRegion& part = piece.parts[part_index_size];
    const int part_index = static_cast<int>(part_index_size);
    const SegmentResult& half = *halves[static_cast<std::size_t>(part.half)];
    const EdgeGrid grid(part.rings);
    RegionTiles tiles(part.rings);
    std::vector<char> on_half_outline(static_cast<std::size_t>(half.mesh3d.V.rows()), 0);
    for (const std::vector<int>& loop : half.topology.boundary_loops)
      for (const int v : loop) on_half_outline[static_cast<std::size_t>(v)] = 1;
    const ClipperLib::IntRect bounds = [&] {
      ClipperLib::Clipper bounds_of;
      bounds_of.AddPath(part.rings.front(), ClipperLib::ptSubject, true);
      return bounds_of.GetBounds();
    }();
    // Triangles no region edge comes near are wholly inside or outside, and so is every group of them
    // connected through such triangles: one point-in-region test per group decides.
    enum : char { kOutside, kFree, kTouched };
    const Eigen::Index face_count = half.mesh3d.F.rows();
    std::vector<char> state(static_cast<std::size_t>(face_count), kOutside);
    for (Eigen::Index f = 0; f < face_count; ++f) {
      const ClipperLib::Path triangle =
          to_clipper_path({half.UV.row(half.mesh3d.F(f, 0)).transpose(), half.UV.row(half.mesh3d.F(f, 1)).transpose(),
                           half.UV.row(half.mesh3d.F(f, 2)).transpose()});
      Box box{triangle[0].X, triangle[0].Y, triangle[0].X, triangle[0].Y};
      for (const auto& q : triangle)
        box = {std::min(box.x0, q.X), std::min(box.y0, q.Y), std::max(box.x1, q.X), std::max(box.y1, q.Y)};
      if (box.x1 < bounds.left || box.x0 > bounds.right || box.y1 < bounds.top || box.y0 > bounds.bottom) continue;
      state[static_cast<std::size_t>(f)] = grid.touches(box) ? kTouched : kFree;
    }
    std::vector<char> keep(static_cast<std::size_t>(face_count), 0), seen(static_cast<std::size_t>(face_count), 0);
    for (Eigen::Index seed = 0; seed < face_count; ++seed) {
      if (state[static_cast<std::size_t>(seed)] != kFree || seen[static_cast<std::size_t>(seed)]) continue;
      Point2 centroid = Point2::Zero();
      for (int k = 0; k < 3; ++k) centroid += half.UV.row(half.mesh3d.F(seed, k)).transpose() / 3.0;
      const char inside = inside_rings(part.rings, to_clipper_path({centroid}).front()) ? 1 : 0;
      std::vector<Eigen::Index> stack{seed};
      seen[static_cast<std::size_t>(seed)] = 1;
      while (!stack.empty()) {
        const Eigen::Index f = stack.back();
        stack.pop_back();
        keep[static_cast<std::size_t>(f)] = inside;
        for (int k = 0; k < 3; ++k) {
          const int g = half.topology.face_across(f, k);
          if (g < 0 || seen[static_cast<std::size_t>(g)] || state[static_cast<std::size_t>(g)] != kFree) continue;
          seen[static_cast<std::size_t>(g)] = 1;
          stack.push_back(g);
        }
      }
    }
    for (Eigen::Index f = 0; f < face_count; ++f) {
      if (state[static_cast<std::size_t>(f)] == kOutside) continue;
      std::array<Point2, 3> uv;
      std::array<Eigen::Vector3d, 3> xyz;
      for (int k = 0; k < 3; ++k) {
        uv[static_cast<std::size_t>(k)] = half.UV.row(half.mesh3d.F(f, k)).transpose();
        xyz[static_cast<std::size_t>(k)] = half.mesh3d.V.row(half.mesh3d.F(f, k)).transpose();
      }
      if (state[static_cast<std::size_t>(f)] == kFree) {
        if (keep[static_cast<std::size_t>(f)]) {
          std::array<int, 3> face;
          for (int k = 0; k < 3; ++k)
            face[static_cast<std::size_t>(k)] =
                vertices.add(xyz[static_cast<std::size_t>(k)], part_index,
                             weldable(xyz[static_cast<std::size_t>(k)], on_half_outline[static_cast<std::size_t>(half.mesh3d.F(f, k))]));
          faces.push_back(face);
        }
        continue;
      }
      const ClipperLib::Path triangle = to_clipper_path({uv[0], uv[1], uv[2]});
      Box box{triangle[0].X, triangle[0].Y, triangle[0].X, triangle[0].Y};
      for (const auto& q : triangle)
        box = {std::min(box.x0, q.X), std::min(box.y0, q.Y), std::max(box.x1, q.X), std::max(box.y1, q.Y)};
      ClipperLib::Clipper clipper;
      clipper.StrictlySimple(true);
      clipper.AddPath(triangle, ClipperLib::ptSubject, true);
      clipper.AddPaths(tiles.around(box), ClipperLib::ptClip, true);
      ClipperLib::Paths pieces_of_triangle;
      clipper.Execute(ClipperLib::ctIntersection, pieces_of_triangle, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
      // Where a tile's side crossed the region's edge inside this triangle the result keeps a point on
      // a straight stretch; no other triangle has it, so it would leave a crack: dropped.
      ClipperLib::CleanPolygons(pieces_of_triangle, 2.0);
      if (pieces_of_triangle.empty()) continue;
      ++surface.clipped_triangles;
      // Barycentric coordinates in the triangle's flattening lift a point to 3D.
      const double area2 = cross(uv[0], uv[1], uv[2]);
      const bool facing = area2 > 0;  // the clipped polygons come counter-clockwise; keep the triangle's turn
      for (const ClipperLib::Path& path : pieces_of_triangle) {
        const std::vector<Point2> polygon = from_clipper_path(path).points;
        std::vector<int> ids;
        for (const Point2& p : polygon) {
          const double w0 = cross(p, uv[1], uv[2]) / area2, w1 = cross(uv[0], p, uv[2]) / area2;
          bool on_outline = false;  // on an outline edge of the triangle, or at a corner on the outline
          for (int k = 0; k < 3; ++k) {
            const Point2& a = uv[static_cast<std::size_t>(k)];
            on_outline = on_outline ||
                         (half.topology.face_across(f, k) < 0 && distance_to_segment(p, a, uv[static_cast<std::size_t>((k + 1) % 3)]) < kOnOutline_mm) ||
                         (on_half_outline[static_cast<std::size_t>(half.mesh3d.F(f, k))] && (p - a).norm() < kOnOutline_mm);
          }
          const Eigen::Vector3d lifted = w0 * xyz[0] + w1 * xyz[1] + (1 - w0 - w1) * xyz[2];
          ids.push_back(vertices.add(lifted, part_index, weldable(lifted, on_outline)));
        }
        for (const auto& t : ear_clip(polygon)) {
          std::array<int, 3> face{ids[static_cast<std::size_t>(t[0])], ids[static_cast<std::size_t>(t[1])], ids[static_cast<std::size_t>(t[2])]};
          if (!facing) std::swap(face[1], face[2]);
          faces.push_back(face);
        }
      }
    }
  }
  // Welding may have merged the corners of a sliver: such a face has no area left.
  std::vector<std::array<int, 3>> kept;
  for (const auto& face : faces)
    if (face[0] != face[1] && face[1] != face[2] && face[0] != face[2]) kept.push_back(face);
  if (kept.empty()) throw EngineError("piece " + piece.name + " has no surface on this last");
  const std::vector<Eigen::Vector3d>& points = vertices.points();
  surface.mesh.V.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t v = 0; v < points.size(); ++v) surface.mesh.V.row(static_cast<Eigen::Index>(v)) = points[v].transpose();
  surface.mesh.F.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (std::size_t f = 0; f < kept.size(); ++f)
    for (int k = 0; k < 3; ++k) surface.mesh.F(static_cast<Eigen::Index>(f), k) = kept[f][static_cast<std::size_t>(k)];
  collapse_short_edges(surface.mesh, kShortestEdge_mm);
  surface.area_mm2 = surface_area(surface.mesh);
  return surface;
}

}  // namespace lastcut
