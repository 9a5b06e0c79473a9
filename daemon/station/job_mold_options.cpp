#include "daemon/station/job_mold_options.hpp"

namespace lastcut::daemon {

MoldOptions job_mold_options(const JobTicket& ticket, const JobsConfig& jobs) {
  MoldOptions options;
  const bool ticket_per_edge = ticket.lasting_mm || ticket.seam_mm || ticket.top_mm;
  const bool default_per_edge = jobs.default_lasting_mm > 0 || jobs.default_seam_mm > 0 || jobs.default_top_mm > 0;
  if (ticket.allowance_mm) {
    options.allowance_mm = *ticket.allowance_mm;
  } else if (ticket_per_edge || default_per_edge) {
    options.edge_allowances = EdgeAllowances{ticket.lasting_mm.value_or(jobs.default_lasting_mm),
                                             ticket.seam_mm.value_or(jobs.default_seam_mm),
                                             ticket.top_mm.value_or(jobs.default_top_mm)};
  } else {
    options.allowance_mm = jobs.default_allowance_mm;
  }
  options.balance_notches.seam_spacing_mm = ticket.seam_notch_spacing_mm.value_or(jobs.default_seam_notch_spacing_mm);
  options.balance_notches.feather_spacing_mm =
      ticket.feather_notch_spacing_mm.value_or(jobs.default_feather_notch_spacing_mm);
  return options;
}

ScanOptions job_scan_options(const JobTicket& ticket, const MoldOptions& mold_options, double max_hole_across_mm,
                             const MoldQualityLimits& quality) {
  ScanOptions options;
  options.mold = mold_options;
  if (ticket.split == "expert") options.segment_options.split_rule = SplitRule::Expert;
  options.segment_options.max_hole_fill_diameter_mm = max_hole_across_mm;
  if (ticket.side == "left") options.side = FootSide::Left;
  if (ticket.side == "right") options.side = FootSide::Right;
  options.quality = quality;
  return options;
}

}  // namespace lastcut::daemon
