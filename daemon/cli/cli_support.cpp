#include "daemon/cli/cli_support.hpp"

#include <cstdio>

namespace lastcut::cli {

void print_error(std::string reason) {
  for (char& c : reason)
    if (c == '\n' || c == '\r') c = ' ';
  std::fprintf(stderr, "lastcut: error: %s\n", reason.c_str());
}

std::optional<FootSide> side_named(const std::string& side) {
  if (side == "left") return FootSide::Left;
  if (side == "right") return FootSide::Right;
  return std::nullopt;
}

ScanResult segmented(const std::filesystem::path& scan, std::optional<FootSide> side) {
  ScanOptions options;
  options.side = side;
  return scan_to_molds(scan, options);
}

}  // namespace lastcut::cli
