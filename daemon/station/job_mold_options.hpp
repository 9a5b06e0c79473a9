#pragma once
// The mold options of one job: the sidecar's allowances and balance notches, else the daemon
// configuration's defaults ([jobs] in lastcut.toml). docs/mold-allowances.md explains the keys.
//   - allowance_mm in the sidecar: one allowance all around (the per-edge defaults are not used);
//   - else any of lasting_mm, seam_mm, top_mm in the sidecar, or a non-zero per-edge default:
//     per-edge allowances, each edge from the sidecar or else its default;
//   - else the uniform default_allowance_mm.
// Balance notch spacings come from the sidecar or else the defaults (0 = off).
#include "daemon/config/daemon_config.hpp"
#include "daemon/job/job_ticket.hpp"
#include "engine/mold/mold.hpp"
#include "engine/scan/scan_to_molds.hpp"

namespace lastcut::daemon {

MoldOptions job_mold_options(const JobTicket& ticket, const JobsConfig& jobs);

// The scan-to-molds options of one job, for its molds or for the last a style's pieces are cut from:
// the ticket's split rule and side, scan holes up to max_hole_across_mm closed, the quality gate.
ScanOptions job_scan_options(const JobTicket& ticket, const MoldOptions& mold_options, double max_hole_across_mm,
                             const MoldQualityLimits& quality);

}  // namespace lastcut::daemon
