#pragma once
// Opening a tty through termios: pseudo-terminals (simulators, socat) and any serial device
// that libserialport cannot enumerate. Raw mode, the given baud, framing and flow control.
#include <string>

#include "drivers/transport/transport.hpp"

namespace lastcut::drivers {

OpenResult open_termios_transport(const std::string& path, const SerialSettings& settings);

// Maps 115200 -> B115200; returns false for a rate termios does not have.
bool baud_to_speed(int baud, unsigned& speed);

}  // namespace lastcut::drivers
