#pragma once
// libserialport backend for real serial ports (USB adapters, on-board UARTs).
#include <string>

#include "drivers/transport/transport.hpp"

namespace lastcut::drivers {

OpenResult open_serialport_transport(const std::string& device, const SerialSettings& settings);

}  // namespace lastcut::drivers
