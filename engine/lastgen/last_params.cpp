#include "engine/lastgen/last_params.hpp"

#include <cmath>
#include <string>

#include "engine/core/engine_error.hpp"

namespace lastcut {

LastParams LastParams::for_eu_size(int eu_size, FootSide side) {
  if (eu_size < 35 || eu_size > 47)
    throw EngineError("EU last size " + std::to_string(eu_size) + " is outside 35..47");
  LastParams params;
  // One Paris point is 2/3 cm; the size number counts them along the last.
  params.length_mm = eu_size * 20.0 / 3.0;
  const double scale = params.length_mm / 270.0;  // proportions of the default (EU 40.5) last
  params.ball_width_mm = 95.0 * scale;
  params.heel_width_mm = 62.0 * scale;
  params.heel_height_mm = 25.0;  // heel pitch is a style choice, not a size property
  params.toe_spring_mm = 12.0 * scale;
  params.top_height_mm = 110.0 * scale;
  params.side = side;
  return params;
}

void validate(const LastParams& p) {
  auto fail = [](const std::string& why) { throw EngineError("last parameters: " + why); };
  if (!(p.length_mm >= 150.0 && p.length_mm <= 380.0)) fail("length must be 150..380 mm");
  if (!(p.ball_width_mm >= 0.25 * p.length_mm && p.ball_width_mm <= 0.5 * p.length_mm))
    fail("ball width must be 25..50% of the length");
  if (!(p.heel_width_mm >= 0.45 * p.ball_width_mm && p.heel_width_mm <= 0.9 * p.ball_width_mm))
    fail("heel width must be 45..90% of the ball width");
  if (!(p.heel_height_mm >= 0.0 && p.heel_height_mm <= 0.3 * p.length_mm)) fail("heel height must be 0..30% of the length");
  if (!(p.toe_spring_mm >= 0.0 && p.toe_spring_mm <= 0.12 * p.length_mm)) fail("toe spring must be 0..12% of the length");
  if (!(p.top_height_mm >= 0.3 * p.length_mm && p.top_height_mm <= 0.6 * p.length_mm))
    fail("top height must be 30..60% of the length");
  if (p.target_triangles < 2000 || p.target_triangles > 2'000'000) fail("triangle count must be 2000..2000000");
  if (!(p.noise_mm >= 0.0 && p.noise_mm <= 2.0)) fail("noise must be 0..2 mm");
  if (p.holes < 0 || p.holes > 50) fail("holes must be 0..50");
  if (p.seams < 0 || p.seams > 8) fail("seams must be 0..8");
  if (!(p.seam_step_mm >= 0 && p.seam_step_mm <= 2)) fail("seam step must be 0..2 mm");
}

}  // namespace lastcut
