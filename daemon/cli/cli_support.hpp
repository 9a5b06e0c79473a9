#pragma once
// What several `lastcut` subcommands share: the one-line error, a scan segmented for a named foot.
#include <filesystem>
#include <optional>
#include <string>

#include "engine/core/foot_side.hpp"
#include "engine/scan/scan_to_molds.hpp"

namespace lastcut::cli {

// "lastcut: error: REASON" on stderr, on one line whatever the reason holds.
void print_error(std::string reason);

// "left" or "right" as a side; anything else (an unset option) names none.
std::optional<FootSide> side_named(const std::string& side);

// The scan through the scan-to-molds pipeline, segmented, for the foot given (none: as it comes).
ScanResult segmented(const std::filesystem::path& scan, std::optional<FootSide> side);

}  // namespace lastcut::cli
