// open_transport: picks the backend from the port name. A tty with a /sys/class/tty/<name>/device
// entry is real hardware (libserialport); anything else that is a terminal, like a pty, goes
// through termios, because libserialport refuses ptys (no sysfs entry, TIOCMGET unsupported).
#include <filesystem>

#include "drivers/transport/serial_ports.hpp"
#include "drivers/transport/serialport_transport.hpp"
#include "drivers/transport/tcp_transport.hpp"
#include "drivers/transport/termios_transport.hpp"
#include "drivers/transport/transport.hpp"

namespace lastcut::drivers {

bool parse_flow_control(std::string_view text, FlowControl& flow) {
  if (text == "none") flow = FlowControl::None;
  else if (text == "xonxoff") flow = FlowControl::XonXoff;
  else if (text == "rtscts") flow = FlowControl::RtsCts;
  else return false;
  return true;
}

std::string to_string(FlowControl flow) {
  switch (flow) {
    case FlowControl::XonXoff: return "xonxoff";
    case FlowControl::RtsCts: return "rtscts";
    case FlowControl::None: break;
  }
  return "none";
}

OpenResult open_transport(const std::string& port, const SerialSettings& settings, double timeout_s) {
  if (port.empty()) return {nullptr, "no port configured"};
  if (port.rfind("tcp://", 0) == 0) return open_tcp_transport(port.substr(6), timeout_s);
  std::string device = port;
  if (port.rfind("usb:", 0) == 0) {
    std::string error;
    if (!resolve_usb_port(port, device, error)) return {nullptr, error};
  }
  std::error_code ec;
  const auto real = std::filesystem::canonical(device, ec);
  if (ec) return {nullptr, "no such port " + device + " (" + ec.message() + ")"};
  const bool hardware = std::filesystem::exists("/sys/class/tty/" + real.filename().string() + "/device", ec);
  if (hardware) return open_serialport_transport(real.string(), settings);
  return open_termios_transport(device, settings);
}

}  // namespace lastcut::drivers
