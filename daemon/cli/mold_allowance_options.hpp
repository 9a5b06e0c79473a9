#pragma once
// `lastcut flatten --lasting MM --seam MM --top MM --balance-notches off|MM|SEAM,FEATHER`: checks
// and parsing of the per-edge allowance and balance notch options (docs/mold-allowances.md).
#include <optional>
#include <string>

#include "engine/mold/mold.hpp"

namespace lastcut::cli {

// "off" -> no notches; "25" -> 25 mm on the centre cut and the feather line; "25,50" -> 25 mm on
// the centre cut, 50 mm on the feather line. Each spacing 0 (off) or 5..500 mm. Empty when the
// text is none of these.
std::optional<BalanceNotches> parse_balance_notches(const std::string& text);

// One line saying what is wrong with the options, or "" when they are usable.
std::string check_edge_allowances(double allowance_mm, const std::optional<double>& lasting_mm,
                                  const std::optional<double>& seam_mm, const std::optional<double>& top_mm,
                                  const std::string& balance_notches);

}  // namespace lastcut::cli
