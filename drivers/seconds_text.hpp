#pragma once
// A time span in an operator message, e.g. "no reply for 2.5 s". Why not to_string(int(t)):
// a fraction of a second printed as "0 s" ("no status reply within 0 s") reads like a bug.
#include <string>

namespace lastcut::drivers {

// "0.25 s", "2.5 s", "30 s": two significant digits below 10 s, whole seconds above. Includes the unit.
std::string seconds_text(double seconds);

}  // namespace lastcut::drivers
