// Tables of HP-GL error numbers (see hpgl_status.hpp for the sources).
#include "drivers/hpgl/hpgl_status.hpp"

namespace lastcut::drivers::hpgl {

std::string device_error_meaning(int code) {
  switch (code) {
    case 0: return "no error";
    case 10: return "output instruction received while another output was in progress";
    case 11: return "invalid byte after ESC.";
    case 12: return "invalid byte in a device-control instruction";
    case 13: return "device-control parameter out of range";
    case 14: return "too many device-control parameters";
    case 15: return "framing, parity or overrun error on the serial line (check baud rate and framing)";
    case 16: return "input buffer overflow: data was lost (flow control is not working)";
    default: return "device error " + std::to_string(code);
  }
}

std::string hpgl_error_meaning(int code) {
  switch (code) {
    case 0: return "no error";
    case 1: return "instruction not recognized";
    case 2: return "wrong number of parameters";
    case 3: return "parameter out of range";
    case 5: return "unknown character set";
    case 6: return "position overflow";
    case 7: return "buffer overflow for polygons or downloadable characters";
    default: return "HP-GL error " + std::to_string(code);
  }
}

}  // namespace lastcut::drivers::hpgl
