// The review step between molds and nesting: each mold whose sidecar names a reference pattern is
// compared with it (engine/compare), the comparison goes into the job's molds folder and report,
// and a corner beyond the configured tolerance holds the job for an operator.
#include <cstdio>
#include <exception>
#include <string>

#include "daemon/station/engine_steps.hpp"
#include "engine/compare/compare_report.hpp"
#include "engine/compare/reference_outline.hpp"
#include "engine/mold/mold_dxf.hpp"

namespace lastcut::daemon {

Result<ReferenceCheck> check_against_references(const std::filesystem::path& job_dir, const JobTicket& ticket,
                                                double corner_tolerance_mm) {
  ReferenceCheck check;
  double worst_margin_mm = 0.0;
  try {
    for (const auto& [mold_name, file] : ticket.references) {
      const std::filesystem::path mold_file = job_dir / kMoldsFolder / (mold_name + ".dxf");
      std::error_code error;
      if (!std::filesystem::is_regular_file(mold_file, error))
        return Status::failure("the sidecar names a reference pattern for the " + mold_name +
                               " mold, but the scan gave no " + mold_name + " mold");
      Mold mold = read_mold_dxf(mold_file);
      mold.name = mold_name;
      const Mold reference = read_reference_outline(job_dir / reference_copy_name(mold_name, file));
      const Comparison comparison = compare_mold(mold, reference);
      check.comparisons[mold_name] = write_comparison(comparison, {mold_file.filename().string(), file},
                                                      corner_tolerance_mm, job_dir / kMoldsFolder,
                                                      "compare-" + mold_name);
      for (const auto& corner : corners_beyond(comparison, corner_tolerance_mm)) {
        if (corner.margin_mm <= worst_margin_mm) continue;
        worst_margin_mm = corner.margin_mm;
        char reason[256];
        std::snprintf(reason, sizeof reason,
                      "held for review: corner %s of the %s mold %.1f mm off the reference pattern (tolerance %.1f mm)",
                      corner.name.c_str(), mold_name.c_str(), corner.margin_mm, corner_tolerance_mm);
        check.hold_reason = reason;
      }
    }
  } catch (const std::exception& error) {
    // EngineError: a refused pattern; anything else (memory, Clipper) must not stop lastcutd either.
    return Status::failure(std::string("reference pattern: ") + error.what());
  }
  return check;
}

}  // namespace lastcut::daemon
