#include "engine/scan/scan_outputs.hpp"

#include <cmath>
#include <system_error>

#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "engine/mold/mold_svg.hpp"

namespace lastcut {

namespace {

namespace fs = std::filesystem;

// JSON has no infinity or NaN: such a measure is reported as null.
nlohmann::json finite_or_null(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

nlohmann::json segment_json(const SegmentResult& segment) {
  const DistortionMeasures& m = segment.measures;
  Point2 lo = Point2::Constant(0.0), hi = Point2::Constant(0.0);
  if (!segment.mold.outline.points.empty()) {
    lo = hi = segment.mold.outline.points.front();
    for (const auto& p : segment.mold.outline.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  }
  nlohmann::json marks = nlohmann::json::array();
  for (const auto& mark : segment.mold.marks)
    marks.push_back({{"name", mark.name}, {"x_mm", mark.position_mm.x()}, {"y_mm", mark.position_mm.y()}});
  return {{"name", segment.name},
          {"triangles", segment.mesh3d.triangle_count()},
          {"vertices", segment.mesh3d.vertex_count()},
          {"flipped", m.flipped_triangles},
          {"D_angle", finite_or_null(m.D_angle)},
          {"D_area", finite_or_null(m.D_area)},
          {"area_3d_mm2", m.area_3d_mm2},
          {"area_2d_mm2", m.area_2d_mm2},
          {"area_error_pct", finite_or_null(m.area_error_pct)},
          {"boundary_3d_mm", m.boundary_3d_mm},
          {"boundary_2d_mm", m.boundary_2d_mm},
          {"boundary_error_pct", finite_or_null(m.boundary_error_pct)},
          {"max_stretch", finite_or_null(m.max_stretch)},
          {"p95_stretch", finite_or_null(m.p95_stretch)},
          {"seconds_flatten", segment.flatten.seconds_total},
          {"iterations", segment.flatten.iterations},
          {"converged", segment.flatten.converged},
          {"outline_points", segment.mold.outline.points.size()},
          {"mold_width_mm", hi.x() - lo.x()},
          {"mold_height_mm", hi.y() - lo.y()},
          {"marks", marks},
          {"files",
           {{"mesh_3d", segment.name + "-3d.obj"},
            {"mesh_flat", segment.name + "-flat.obj"},
            {"dxf", segment.name + ".dxf"},
            {"svg", segment.name + ".svg"}}}};
}

nlohmann::json intake_report_json(const IntakeReport& intake) {
  return {{"format", intake.format},
          {"unit_note", intake.unit_note},
          {"triangles_read", intake.triangles_read},
          {"duplicate_vertices_merged", intake.duplicate_vertices_merged},
          {"degenerate_faces_removed", intake.degenerate_faces_removed},
          {"duplicate_faces_removed", intake.duplicate_faces_removed},
          {"faces_flipped", intake.faces_flipped},
          {"non_manifold_faces_removed", intake.non_manifold_faces_removed},
          {"loose_components_removed", intake.loose_components_removed},
          {"boundary_loops", intake.boundary_loops},
          {"notes", intake.notes}};
}

nlohmann::json profile_json(const std::vector<StageTime>& stages) {
  nlohmann::json profile = nlohmann::json::array();
  for (const StageTime& stage : stages) profile.push_back({{"stage", stage.stage}, {"seconds", stage.seconds}});
  return profile;
}

}  // namespace

nlohmann::json scan_report_json(const ScanResult& result) {
  nlohmann::json report = {{"input", result.input},
                           {"units", "mm"},
                           {"seconds_total", result.seconds_total},
                           {"intake", intake_report_json(result.intake)},
                           {"notes", result.notes},
                           {"warnings", result.warnings},
                           {"repairs", nlohmann::json::array()},
                           {"segments", nlohmann::json::array()}};
  for (const HoleRepair& repair : result.repairs)
    report["repairs"].push_back({{"kind", "hole closed"},
                                 {"across_mm", repair.across_mm},
                                 {"patch_vertices", repair.patch_vertices},
                                 {"patch", repair.fan ? "fan" : "faired rings"}});
  report["side"] = result.side ? nlohmann::json(std::string(to_string(*result.side))) : nlohmann::json();
  for (const auto& segment : result.segments) report["segments"].push_back(segment_json(segment));
  report["quality"] = result.quality.to_json();
  report["profile"] = profile_json(result.profile);
  return report;
}

nlohmann::json write_scan_outputs(const ScanResult& result, const fs::path& out_dir) {
  std::error_code error;
  fs::create_directories(out_dir, error);
  if (error) throw EngineError("cannot create output folder " + out_dir.string() + ": " + error.message());
  StageClock clock;
  for (const auto& segment : result.segments) {
    write_obj(out_dir / (segment.name + "-3d.obj"), segment.mesh3d);
    clock.lap(segment.name + ": write 3d obj");
    write_obj_2d(out_dir / (segment.name + "-flat.obj"), segment.UV, segment.mesh3d.F);
    clock.lap(segment.name + ": write flat obj");
    write_mold_dxf(out_dir / (segment.name + ".dxf"), segment.mold);
    clock.lap(segment.name + ": write dxf");
    write_mold_svg(out_dir / (segment.name + ".svg"), segment.mold, segment.UV, segment.mesh3d.F,
                   triangle_strain(segment.measures));
    clock.lap(segment.name + ": write svg");
  }
  nlohmann::json report_json = scan_report_json(result);
  for (const StageTime& stage : clock.stages())
    report_json["profile"].push_back({{"stage", stage.stage}, {"seconds", stage.seconds}});
  const Status written = write_file_durably(out_dir / "report.json", report_json.dump(2) + "\n");
  if (!written) throw EngineError(written.error());
  return report_json;
}

}  // namespace lastcut
