#include "drivers/seconds_text.hpp"

#include <cmath>
#include <cstdio>

namespace lastcut::drivers {

std::string seconds_text(double seconds) {
  char text[32];
  if (!std::isfinite(seconds) || seconds >= 9.95) {
    std::snprintf(text, sizeof text, "%.0f s", std::isfinite(seconds) ? seconds : 0.0);
  } else {
    std::snprintf(text, sizeof text, "%.2g s", seconds < 0 ? 0.0 : seconds);
  }
  return text;
}

}  // namespace lastcut::drivers
