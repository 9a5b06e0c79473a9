// Scan -> molds for one job (engine/scan), plus pieces.json: the mold outlines and notches in
// a small file of our own, so that nesting after a restart needs no recomputation.
#include <spdlog/spdlog.h>

#include "daemon/pipeline/engine_steps.hpp"
#include "daemon/spool/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/scan/scan_outputs.hpp"
#include "engine/scan/scan_to_molds.hpp"

namespace lastcut::daemon {
namespace {

nlohmann::json point_json(const Point2& point) { return nlohmann::json::array({point.x(), point.y()}); }

nlohmann::json pieces_json(const ScanResult& result) {
  nlohmann::json pieces = nlohmann::json::array();
  for (const SegmentResult& segment : result.segments) {
    nlohmann::json outline = nlohmann::json::array();
    for (const Point2& point : segment.mold.outline.points) outline.push_back(point_json(point));
    nlohmann::json marks = nlohmann::json::array();
    for (const MoldMark& mark : segment.mold.marks) {
      const Point2 end = mark.position_mm + kNotchLength_mm * mark.inward_direction;
      marks.push_back({{"name", mark.name}, {"from", point_json(mark.position_mm)}, {"to", point_json(end)}});
    }
    pieces.push_back({{"name", segment.name}, {"outline", outline}, {"marks", marks}});
  }
  nlohmann::json json{{"pieces", pieces}};
  if (result.side) json["side"] = std::string(to_string(*result.side));
  return json;
}

}  // namespace

MoldsOutcome compute_molds(const std::filesystem::path& scan, const std::filesystem::path& job_dir,
                           const JobTicket& ticket, double default_allowance_mm) {
  MoldsOutcome outcome;
  try {
    ScanOptions options;
    options.mold.allowance_mm = ticket.allowance_mm.value_or(default_allowance_mm);
    const ScanResult result = scan_to_molds(scan, options);
    if (result.segments.empty()) {
      outcome.error = "no mold could be made from the scan";
      return outcome;
    }
    write_scan_outputs(result, job_dir / kMoldsFolder);
    outcome.measures = scan_report_json(result);
    if ((ticket.side == "left" || ticket.side == "right") && result.side &&
        ticket.side != std::string(to_string(*result.side))) {
      outcome.measures["warning"] = "the sidecar says " + ticket.side + ", the scan looks like a " +
                                    std::string(to_string(*result.side)) + " last";
    }
    if (std::string error = write_file_durably(job_dir / kPiecesFile, pieces_json(result).dump() + "\n");
        !error.empty()) {
      outcome.error = "molds made but not saved: " + error;
      return outcome;
    }
    outcome.piece_count = static_cast<int>(result.segments.size());
  } catch (const EngineError& error) {
    outcome.error = error.what();
  } catch (const std::bad_alloc&) {
    outcome.error = "the scan is too large for this machine's memory";
  }
  return outcome;
}

}  // namespace lastcut::daemon
