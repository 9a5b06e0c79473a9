#pragma once
// The smallest valid lastcutd configuration (14 lines, ends with a newline): one strip material,
// one grbl cutter. Configuration tests append the table they test to it, so a refusal's line
// number is the table's line in this text plus 14.
#include <string>

namespace lastcut::testing {

inline const std::string kMinimalDaemonConfig = R"([paths]
watch = "in"
spool = "spool"
machines = "machines"
[jobs]
default_material = "calf"
default_cutter = "a"
[materials.calf]
width_mm = 500
length_mm = 900
[cutters.a]
protocol = "grbl"
port = "/dev/ttyUSB0"
machine = "grbl-drag-knife"
)";

}  // namespace lastcut::testing
