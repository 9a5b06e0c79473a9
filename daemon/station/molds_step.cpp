// Scan -> molds for one job (engine/scan), then the molds as nest items (engine/nest/mold_items)
// in the engine's JSON, so that nesting after a restart needs no recomputation and reads the same
// form `lastcut nest` reads.
#include "daemon/station/engine_steps.hpp"
#include "daemon/station/job_mold_options.hpp"
#include "daemon/station/piece_label_text.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/mold_items.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/scan/scan_outputs.hpp"
#include "engine/scan/scan_to_molds.hpp"

namespace lastcut::daemon {
namespace {

// The foot is the scan's (the molds are its geometry); the sidecar's only when the scan's is unknown.
std::string foot_of(const ScanResult& result, const JobTicket& ticket) {
  if (result.side) return std::string(to_string(*result.side));
  if (ticket.side == "left" || ticket.side == "right") return ticket.side;
  return "";
}

std::vector<NestItem> job_items(const ScanResult& result, const JobTicket& ticket, const std::string& scan_name) {
  std::vector<Mold> molds;
  for (const SegmentResult& segment : result.segments) {
    molds.push_back(segment.mold);
    molds.back().name = segment.name;
  }
  const std::string foot = foot_of(result, ticket);
  MoldNestSpec spec;
  spec.copies = ticket.quantity;
  spec.mirrored_twins = ticket.side == "pair";  // the twin is the same half of the other foot
  spec.label = [&](const Mold& mold, bool twin) {
    return piece_label_text({ticket.order, scan_name, ticket.size, twin ? opposite_foot(foot) : foot, mold.name});
  };
  return items_from_molds(molds, spec);
}

}  // namespace

Result<MoldsMade> compute_molds(const std::filesystem::path& scan, const std::filesystem::path& job_dir,
                                const JobTicket& ticket, const MoldOptions& mold_options, double max_hole_across_mm,
                                const MoldQualityLimits& quality) {
  return guarded_job_step(job_dir, [&]() -> Result<MoldsMade> {
    const ScanResult result = scan_to_molds(scan, job_scan_options(ticket, mold_options, max_hole_across_mm, quality));
    if (result.segments.empty()) return Status::failure("no mold could be made from the scan");
    MoldsMade made;
    made.measures = write_scan_outputs(result, job_dir / kMoldsFolder);
    made.piece_count = static_cast<int>(result.segments.size());
    if (!result.quality.passed()) {
      made.hold_reason = result.quality.reason() + "; stretch pictures in molds/";
      return made;
    }
    // A sidecar side that contradicts the scan is among result.warnings (orient_last), in measures.
    return save_job_items(job_dir, job_items(result, ticket, scan.filename().string()), made, "molds");
  }, "the scan is too large for this machine's memory");
}

}  // namespace lastcut::daemon
