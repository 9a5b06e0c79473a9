#pragma once
// Meanings of HP-GL device errors, for the log and the operator.
// ESC.E (RS-232 device-control errors) and OE (HP-GL instruction errors), after the HP 7475A /
// 7550A interfacing and programming manuals ("Output Error" and "ESC.E Output Extended Error").
#include <string>

namespace lastcut::drivers::hpgl {

std::string device_error_meaning(int code);   // ESC.E: 0, 10..16
std::string hpgl_error_meaning(int code);     // OE: 0..7

}  // namespace lastcut::drivers::hpgl
