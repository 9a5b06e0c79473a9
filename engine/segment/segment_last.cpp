#include "engine/segment/segment_last.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

#include "engine/core/engine_error.hpp"
#include "engine/mesh/fill_holes.hpp"
#include "engine/segment/contour_fields.hpp"
#include "engine/segment/level_set_cut.hpp"
#include "engine/core/mesh_topology.hpp"
#include "engine/segment/region_contour.hpp"
#include "engine/segment/segment_halves.hpp"
#include "engine/segment/split_plane.hpp"
#include "engine/segment/surface_regions.hpp"

namespace lastcut {
namespace {

// Normals are averaged over this many rings on a mesh with kNormalReferenceEdgeMm edges before
// classifying; on other meshes the ring count follows so the radius in mm stays the same.
constexpr double kNormalSmoothingPasses = 3.0;
constexpr double kNormalReferenceEdgeMm = 3.0;
constexpr double kSnapFraction = 0.1;      // crossings within 10 % of an edge end snap to the vertex
constexpr double kReferenceEdgeMm = 2.0;   // smoothing_passes are counted on a mesh with edges this long
constexpr double kGeometricSmoothingPasses = 5.0;   // on the height and depth fields, against scanner noise
constexpr double kMaxFitRmsMm = 0.8;       // a sole or top cut fitted worse than this is not used
constexpr double kPlaneBandMm = 0.25;      // a face with all corners this close to the top plane is on it,
constexpr double kPlaneBandRms = 3.0;      // or this many times the plane fit's RMS (scanner noise)
constexpr double kSharpRimPassShare = 0.25;  // of the geometric passes, below a sharp rim
constexpr double kSharpRimTurnRad = 50.0 * std::numbers::pi / 180.0;  // a crease turns more in one edge

std::string fixed(double value, int decimals) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(decimals);
  out << value;
  return out.str();
}

double mean_edge_length_mm(const TriMesh& mesh) {
  double sum = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) sum += (mesh.V.row(mesh.F(f, k)) - mesh.V.row(mesh.F(f, (k + 1) % 3))).norm();
  return sum / (3.0 * static_cast<double>(mesh.F.rows()));
}

double region_area(const std::vector<char>& region, const Eigen::VectorXd& areas) {
  double sum = 0.0;
  for (std::size_t f = 0; f < region.size(); ++f)
    if (region[f]) sum += areas(static_cast<Eigen::Index>(f));
  return sum;
}

// The region's indicator (share of each vertex's surrounding area inside the region) after the
// moving average of eq. 22, minus 1/2: its zero level set is the region boundary smoothed at the
// scale of a few edges, lying exactly on the surface. Used where the geometric fields
// (contour_fields.hpp) do not apply.
Eigen::VectorXd smoothed_indicator(const TriMesh& mesh, const std::vector<char>& region,
                                   const Eigen::VectorXd& areas, double passes) {
  const Eigen::Index vertex_count = mesh.V.rows();
  Eigen::VectorXd inside = Eigen::VectorXd::Zero(vertex_count), total = Eigen::VectorXd::Zero(vertex_count);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      total(mesh.F(f, k)) += areas(f);
      if (region[static_cast<std::size_t>(f)]) inside(mesh.F(f, k)) += areas(f);
    }
  const Eigen::VectorXd value = (total.array() > 0.0).select(inside.array() / total.array(), 0.0);
  return smooth_vertex_field(mesh, areas, value, passes).array() - 0.5;
}

std::vector<Eigen::Vector3d> loop_points(const TriMesh& mesh, const std::vector<int>& loop) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(loop.size());
  for (int v : loop) points.emplace_back(mesh.V.row(v).transpose());
  return points;
}

// The faces with all corners on the fitted top plane (within a band that grows with the fit's RMS,
// so that scanner noise does not break the plane up), #F.
std::vector<char> faces_on_top_plane(const TriMesh& mesh, const ContourField& top_field, double depth_mm) {
  const double band_mm = std::max(kPlaneBandMm, kPlaneBandRms * top_field.fit_rms_mm);
  std::vector<char> plane_faces(static_cast<std::size_t>(mesh.F.rows()), 0);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    bool flat = true;
    for (int k = 0; k < 3; ++k) flat = flat && std::abs(top_field.values(mesh.F(f, k)) - depth_mm) < band_mm;
    plane_faces[static_cast<std::size_t>(f)] = flat;
  }
  return plane_faces;
}

// Whether the plane's faces meet the side at a crease: the median turn of the normal across the edges
// between a plane face and a side face exceeds kSharpRimTurnRad. A rounded rim (a fillet a few
// edges wide, as a worn or sanded cut) turns 15-35 deg per edge there (measured on the remeshed
// last, with 0.2 mm noise and 4x denser), the Bezier last 73 deg.
bool meets_at_sharp_rim(const TriMesh& mesh, const MeshTopology& topology, const std::vector<char>& plane_faces) {
  const Eigen::MatrixXd normals = triangle_normals(mesh);
  std::vector<double> turns;
  for (std::size_t h = 0; h < topology.across.size(); ++h) {
    const std::size_t f = h / 3;
    const int other = topology.across[h];
    if (!plane_faces[f] || other < 0 || plane_faces[static_cast<std::size_t>(other / 3)]) continue;
    const double cosine = normals.row(static_cast<Eigen::Index>(f)).dot(normals.row(other / 3));
    turns.push_back(std::acos(std::clamp(cosine, -1.0, 1.0)));
  }
  if (turns.empty()) return false;
  std::nth_element(turns.begin(), turns.begin() + static_cast<std::ptrdiff_t>(turns.size() / 2), turns.end());
  return turns[turns.size() / 2] > kSharpRimTurnRad;
}

}  // namespace

BandCut cut_band(const OrientedLast& last, const SegmentOptions& options) {
  return cut_band(last, build_mesh_topology(last.mesh.F, last.mesh.V.rows()), options);
}

BandCut cut_band(const OrientedLast& last, const MeshTopology& last_topology, const SegmentOptions& options) {
  if (!(options.sole_angle_rad < 0.0 && options.top_angle_rad > 0.0))
    throw EngineError("segmentation angles must be negative for the sole and positive for the top");
  if (options.smoothing_passes < 0) throw EngineError("segmentation smoothing passes must not be negative");
  if (!(options.feather_height_mm > 0.0 && options.rim_depth_mm > 0.0))
    throw EngineError("the feather line height and the top rim depth must be positive (mm)");
  BandCut result;
  result.side = last.side;
  result.side_unnamed = last.side_unnamed;
  result.snap_fraction = kSnapFraction;
  TriMesh& mesh = result.mesh;
  mesh = last.mesh;
  MeshTopology topology = last_topology;  // hole filling changes it along with the mesh
  result.repairs = fill_holes(mesh, topology, options.max_hole_fill_diameter_mm);
  if (!result.repairs.empty()) {
    std::string sizes;
    for (const HoleRepair& repair : result.repairs)
      sizes += (sizes.empty() ? "" : ", ") + fixed(repair.across_mm, 1) + " mm across (" +
               std::to_string(repair.patch_vertices) + " patch vertices" + (repair.fan ? ", fan: may fold" : "") + ")";
    result.notes.push_back("closed " + std::to_string(result.repairs.size()) + " scan hole" +
                           (result.repairs.size() == 1 ? "" : "s") + " with a smooth patch: " + sizes);
  }

  // Step 2: sole and top regions, and their contours (Dijkstra, then eq. 22).
  const Eigen::VectorXd areas = triangle_areas(mesh);
  const double edge_mm = mean_edge_length_mm(mesh);
  const Eigen::VectorXd elevation =
      smoothed_elevation_rad(mesh, topology, kNormalSmoothingPasses * std::pow(kNormalReferenceEdgeMm / edge_mm, 2));
  const std::vector<char> sole = sole_region(mesh, topology, elevation, areas, options.sole_angle_rad);
  const std::vector<char> top = top_region(mesh, topology, elevation, areas, options.top_angle_rad);
  for (std::size_t f = 0; f < sole.size(); ++f)
    if (sole[f] && top[f]) throw EngineError("the sole and the top cut touch: the last is not standing upright");
  const double total_area = areas.sum();
  result.notes.push_back("sole " + fixed(100.0 * region_area(sole, areas) / total_area, 1) + " % of the surface, top cut " +
                         fixed(100.0 * region_area(top, areas) / total_area, 1) + " %");

  // Steps 2 and 5: the feather line and the top rim as zero level sets of the smoothed region
  // indicators, cut into the mesh. The passes are meant for the reference edge length; on a finer
  // or coarser mesh they are scaled so the curves are smoothed over the same distance in mm
  // (diffusion spreads as sqrt(passes)).
  Eigen::MatrixXd& fields = result.fields;
  fields = Eigen::MatrixXd::Zero(mesh.V.rows(), 3);
  const double field_passes = options.smoothing_passes * std::pow(kReferenceEdgeMm / edge_mm, 2);
  // Where the fits hold, the curves are placed by the shape (a height above the sole, a depth
  // below the top plane), lightly smoothed against scanner noise; else by the classification.
  const double geometric_passes = kGeometricSmoothingPasses * std::pow(kReferenceEdgeMm / edge_mm, 2);
  const std::optional<ContourField> sole_field =
      sole_height_field(mesh, topology, sole, areas, options.feather_height_mm, kMaxFitRmsMm);
  const std::optional<ContourField> top_field = top_plane_field(mesh, topology, top, areas, options.rim_depth_mm, kMaxFitRmsMm);
  // Clamped to a ramp symmetric about the curve before the moving average: otherwise the steep
  // drop of the height down the side walls would drag the averaged curve onto the flat part.
  auto ramp = [&](const Eigen::VectorXd& field, double half_width_mm) {
    return smooth_vertex_field(mesh, areas, field.cwiseMax(-half_width_mm).cwiseMin(half_width_mm), geometric_passes);
  };
  fields.col(kSoleField) = sole_field ? ramp(sole_field->values, options.feather_height_mm)
                                      : smoothed_indicator(mesh, sole, areas, field_passes);
  if (top_field) {
    const std::vector<char> plane_faces = faces_on_top_plane(mesh, *top_field, options.rim_depth_mm);
    if (meets_at_sharp_rim(mesh, topology, plane_faces)) {
      // A sharp rim (a crease; the Bezier last, a milled cut): the cap is a plane, so its vertices
      // need no averaging with the side's, and below the crease the height falls steadily, so its
      // average does not move the level set and no ramp is needed. A ramp would put every crossing
      // mid-edge wherever the first vertex row below the crease is deeper than it, and averaging
      // across the crease pulls the crease's own vertices below the curve (docs/subdivision.md).
      // Fewer passes: noise along a steep side's normal hardly changes its height, while the average
      // of a side that curves away below the rim lifts the curve (by 20 % of the depth at full passes).
      fields.col(kTopField) = smooth_vertex_field(mesh, areas, top_field->values, kSharpRimPassShare * geometric_passes, plane_faces);
    } else {
      fields.col(kTopField) = ramp(top_field->values, options.rim_depth_mm);
    }
  } else {
    fields.col(kTopField) = smoothed_indicator(mesh, top, areas, field_passes);
  }
  result.notes.push_back(sole_field ? "feather line " + fixed(options.feather_height_mm, 2) + " mm above the sole surface (fitted within " +
                                           fixed(sole_field->fit_rms_mm, 2) + " mm RMS)"
                                     : std::string("the sole is not a smooth surface: feather line from the normal angle"));
  result.notes.push_back(top_field ? "top rim " + fixed(options.rim_depth_mm, 2) + " mm below the top cut plane (fitted within " +
                                         fixed(top_field->fit_rms_mm, 2) + " mm RMS)"
                                   : std::string("the top cut is not flat: top rim from the normal angle"));
  for (int column : {kSoleField, kTopField}) cut_along_zero_level(mesh, fields, column, kSnapFraction);

  // Step 3: the split plane from those smooth curves (not from the staircase of mesh edges, whose
  // shape follows the triangulation). The two cuts split faces and add vertices: the cut mesh's topology.
  const MeshTopology level_topology = build_mesh_topology(mesh.F, mesh.V.rows());
  auto level_loop = [&](int column) {
    std::vector<char> region(static_cast<std::size_t>(mesh.F.rows()));
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
      region[static_cast<std::size_t>(f)] =
          fields(mesh.F(f, 0), column) + fields(mesh.F(f, 1), column) + fields(mesh.F(f, 2), column) > 0.0;
    return smooth_closed_polyline(loop_points(mesh, region_boundary_loop(mesh, level_topology, region)), 0, kReferenceEdgeMm);
  };
  result.lower_loop = level_loop(kSoleField);
  result.upper_loop = level_loop(kTopField);
  return result;
}

SplitPlane place_split_plane(const BandCut& band, const SegmentOptions& options) {
  return options.split_rule == SplitRule::Expert
             ? expert_split_plane(band.lower_loop, band.upper_loop, options.expert, band.side)
             : split_plane(band.lower_loop, band.upper_loop, options.plane_t, band.side);
}

Segmentation split_band(const BandCut& band, const SplitPlane& plane) {
  Segmentation result;
  result.notes = band.notes;
  result.repairs = band.repairs;
  result.plane = plane;
  TriMesh mesh = band.mesh;
  Eigen::MatrixXd fields = band.fields;
  result.notes.push_back("split plane normal (" + fixed(plane.normal.x(), 3) + ", " + fixed(plane.normal.y(), 3) + ", " +
                         fixed(plane.normal.z(), 3) + ") through the top centre (" + fixed(plane.T1.x(), 1) + ", " +
                         fixed(plane.T1.y(), 1) + ", " + fixed(plane.T1.z(), 1) + ") mm");

  // Step 4: cut along the plane.
  fields.col(kPlaneField) = (mesh.V * plane.normal).array() + plane.offset;
  cut_along_zero_level(mesh, fields, kPlaneField, band.snap_fraction);

  enum Label : int { kSole = 0, kTop = 1, kMedial = 2, kLateral = 3 };
  std::vector<int> labels(static_cast<std::size_t>(mesh.F.rows()));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d mean = (fields.row(mesh.F(f, 0)) + fields.row(mesh.F(f, 1)) + fields.row(mesh.F(f, 2))).transpose() / 3.0;
    labels[static_cast<std::size_t>(f)] = mean(kSoleField) > 0.0 ? kSole
                                          : mean(kTopField) > 0.0 ? kTop
                                          : mean(kPlaneField) > 0.0 ? kMedial
                                                                     : kLateral;
  }
  // The plane cut split faces and added vertices: the topology of the mesh the halves come from.
  const MeshTopology cut_topology = build_mesh_topology(mesh.F, mesh.V.rows());
  // An unnamed symmetric last is split as a left one (medial -Y), named by side of Y instead.
  result.medial = extract_half(mesh, cut_topology, labels, kMedial, fields, band.side_unnamed ? kNeutralHalfMinusY : "medial");
  result.lateral = extract_half(mesh, cut_topology, labels, kLateral, fields, band.side_unnamed ? kNeutralHalfPlusY : "lateral");

  // The curves the halves were cut along, for previews.
  for (auto [label, contour] : {std::pair{kSole, &result.lower_contour}, std::pair{kTop, &result.upper_contour}}) {
    std::vector<char> region(labels.size());
    for (std::size_t f = 0; f < labels.size(); ++f) region[f] = labels[f] == label;
    *contour = loop_points(mesh, region_boundary_loop(mesh, cut_topology, region));
  }
  const double medial_area = surface_area(result.medial.mesh), lateral_area = surface_area(result.lateral.mesh);
  result.notes.push_back(result.medial.name + " half " + fixed(medial_area / 100.0, 0) + " cm^2, " + result.lateral.name +
                         " half " + fixed(lateral_area / 100.0, 0) + " cm^2");
  return result;
}

Segmentation segment_last(const OrientedLast& last, const SegmentOptions& options) {
  return segment_last(last, build_mesh_topology(last.mesh.F, last.mesh.V.rows()), options);
}

Segmentation segment_last(const OrientedLast& last, const MeshTopology& topology, const SegmentOptions& options) {
  const BandCut band = cut_band(last, topology, options);
  const SplitPlane plane = place_split_plane(band, options);
  Segmentation result = split_band(band, plane);
  if (options.split_rule == SplitRule::Expert)
    result.notes.push_back("expert split: second toe at (" + fixed(plane.T2.x(), 1) + ", " + fixed(plane.T2.y(), 1) + ", " +
                           fixed(plane.T2.z(), 1) + ") mm, heel middle at (" + fixed(plane.T3.x(), 1) + ", " +
                           fixed(plane.T3.y(), 1) + ", " + fixed(plane.T3.z(), 1) + ") mm");
  return result;
}

}  // namespace lastcut
