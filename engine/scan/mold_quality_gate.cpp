#include "engine/scan/mold_quality_gate.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include "engine/core/decimal_text.hpp"
#include "engine/core/edge_path.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/core/mesh_topology.hpp"

namespace lastcut {
namespace {

std::vector<int> boundary_vertices(const MeshTopology& topology) {
  std::vector<int> vertices;
  for (const auto& loop : topology.boundary_loops) vertices.insert(vertices.end(), loop.begin(), loop.end());
  return vertices;
}

// Enough digits to tell a measure from its limit: "2.0182 > 2.02" would be needless, "3.31 > 2.02" is not.
std::string number(double value) {
  if (!std::isfinite(value)) return "not a number";
  std::string text = fixed_text(value, std::fabs(value) >= 10 ? 1 : std::fabs(value) >= 2 ? 3 : 2);
  while (text.back() == '0') text.pop_back();  // "2.2", not "2.200"; fixed_text always has a point
  if (text.back() == '.') text.pop_back();
  return text;
}

}  // namespace

MoldSpan measure_mold_span(const TriMesh& mesh3d, const MeshTopology& topology, const Eigen::MatrixXd& UV) {
  const std::vector<int> outline = boundary_vertices(topology);
  if (outline.size() < 2) throw EngineError("the flattened half has no outline to measure");
  MoldSpan span;
  int a = outline[0], b = outline[1];
  for (std::size_t i = 0; i < outline.size(); ++i)
    for (std::size_t j = i + 1; j < outline.size(); ++j) {
      const double d = (UV.row(outline[i]) - UV.row(outline[j])).squaredNorm();
      if (d > span.span_2d_mm) {
        span.span_2d_mm = d;
        a = outline[i];
        b = outline[j];
      }
    }
  span.span_2d_mm = std::sqrt(span.span_2d_mm);
  span.along_surface_mm = shortest_edge_path(mesh3d, topology, a, b).length_mm;
  if (!std::isfinite(span.along_surface_mm))
    throw EngineError("the flattened half falls apart: its farthest outline points are not connected");
  return span;
}

bool MoldQuality::passed() const {
  for (const HalfVerdict& half : halves)
    if (!half.breaches.empty()) return false;
  return true;
}

std::string MoldQuality::reason() const {
  std::string line;
  for (const HalfVerdict& half : halves) {
    if (half.breaches.empty()) continue;
    line += line.empty() ? "mold quality: " : "; ";
    line += half.name;
    for (std::size_t i = 0; i < half.breaches.size(); ++i) line += (i == 0 ? " " : ", ") + half.breaches[i];
  }
  return line;
}

nlohmann::json MoldQuality::to_json() const {
  nlohmann::json document{{"passed", passed()},
                          {"reason", reason()},
                          {"limits",
                           {{"max_D_angle", limits.max_D_angle},
                            {"max_D_area", limits.max_D_area},
                            {"max_stretch", limits.max_stretch},
                            {"max_p95_stretch", limits.max_p95_stretch},
                            {"require_converged", limits.require_converged},
                            {"max_length_excess_pct", limits.max_length_excess_pct}}},
                          {"halves", nlohmann::json::array()}};
  for (const HalfVerdict& half : halves)
    document["halves"].push_back({{"name", half.name},
                                  {"span_2d_mm", half.span.span_2d_mm},
                                  {"along_surface_mm", half.span.along_surface_mm},
                                  {"excess_pct", half.span.excess_pct()},
                                  {"breaches", half.breaches}});
  return document;
}

HalfVerdict judge_half(const std::string& name, const TriMesh& mesh3d, const MeshTopology& topology, const Eigen::MatrixXd& UV,
                       const DistortionMeasures& m, bool converged, const MoldQualityLimits& limits) {
  HalfVerdict half;
  half.name = name;
  // Written as "not within" so that a NaN measure (a degenerate flattening) is a breach too.
  const auto above = [&half](const char* what, double value, double limit) {
    if (!(value <= limit)) half.breaches.push_back(std::string(what) + " " + number(value) + " > " + number(limit));
  };
  above("D_angle", m.D_angle, limits.max_D_angle);
  above("D_area", m.D_area, limits.max_D_area);
  above("max stretch", m.max_stretch, limits.max_stretch);
  above("p95 stretch", m.p95_stretch, limits.max_p95_stretch);
  if (m.flipped_triangles > 0) half.breaches.push_back(std::to_string(m.flipped_triangles) + " flipped triangles");
  if (limits.require_converged && !converged) half.breaches.push_back("ARAP not converged");
  half.span = measure_mold_span(mesh3d, topology, UV);
  if (!(half.span.excess_pct() <= limits.max_length_excess_pct))
    half.breaches.push_back("mold " + fixed_text(half.span.span_2d_mm, 0) + " mm long where the surface is " +
                            fixed_text(half.span.along_surface_mm, 0) + " mm (+" + fixed_text(half.span.excess_pct(), 1) +
                            " % > " + number(limits.max_length_excess_pct) + " %)");
  return half;
}

}  // namespace lastcut
