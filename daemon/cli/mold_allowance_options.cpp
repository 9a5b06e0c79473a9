#include "daemon/cli/mold_allowance_options.hpp"

#include <charconv>
#include <cstdio>
#include <cmath>

namespace lastcut::cli {

namespace {

std::optional<double> spacing_of(const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  if (value != 0.0 && !(value >= 5.0 && value <= 500.0)) return std::nullopt;
  return value;
}

std::string format_mm(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

std::optional<BalanceNotches> parse_balance_notches(const std::string& text) {
  if (text == "off") return BalanceNotches{};
  const auto comma = text.find(',');
  const auto seam = spacing_of(text.substr(0, comma));
  const auto feather = comma == std::string::npos ? seam : spacing_of(text.substr(comma + 1));
  if (!seam || !feather) return std::nullopt;
  return BalanceNotches{*seam, *feather};
}

std::string check_edge_allowances(double allowance_mm, const std::optional<double>& lasting_mm,
                                  const std::optional<double>& seam_mm, const std::optional<double>& top_mm,
                                  const std::string& balance_notches) {
  for (const auto& [flag, value] : {std::pair{"--lasting", lasting_mm}, std::pair{"--seam", seam_mm}, std::pair{"--top", top_mm}})
    if (value && !(*value >= 0.0 && *value <= 50.0))
      return std::string(flag) + " must be between 0 and 50 mm, not " + format_mm(*value);
  if (allowance_mm > 0.0 && (lasting_mm || seam_mm || top_mm))
    return "give --allowance (all edges) or --lasting/--seam/--top (per edge), not both";
  if (!parse_balance_notches(balance_notches))
    return "--balance-notches must be off, a spacing in mm (0 or 5 to 500) or SEAM_MM,FEATHER_MM, not \"" +
           balance_notches + "\"";
  return "";
}

}  // namespace lastcut::cli
