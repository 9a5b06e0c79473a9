// libserialport backend: the library opens and configures the port (it knows the quirks of
// USB adapters); reads and writes then go through the port's descriptor with poll timeouts.
#include "drivers/transport/serialport_transport.hpp"

#include <libserialport.h>

#include "drivers/transport/fd_transport.hpp"

namespace lastcut::drivers {

namespace {

std::string last_error() {
  char* message = sp_last_error_message();
  std::string text = message ? message : "unknown error";
  sp_free_error_message(message);
  return text;
}

class SerialportTransport : public FdTransport {
 public:
  SerialportTransport(sp_port* port, int fd, std::string description, int baud)
      : FdTransport(fd, std::move(description), baud, true, false), port_(port) {}
  ~SerialportTransport() override { SerialportTransport::close(); }
  void close() override {
    FdTransport::close();
    if (port_ != nullptr) {
      sp_close(port_);
      sp_free_port(port_);
      port_ = nullptr;
    }
  }

 private:
  sp_port* port_;
};

}  // namespace

OpenResult open_serialport_transport(const std::string& device, const SerialSettings& settings) {
  sp_port* port = nullptr;
  if (sp_get_port_by_name(device.c_str(), &port) != SP_OK) return {nullptr, "no serial port " + device + ": " + last_error()};
  if (sp_open(port, SP_MODE_READ_WRITE) != SP_OK) {
    const std::string why = last_error();
    sp_free_port(port);
    return {nullptr, "cannot open " + device + ": " + why + " (is another program using it? is the user in group dialout?)"};
  }
  const sp_parity parity = settings.parity == 'E' ? SP_PARITY_EVEN : settings.parity == 'O' ? SP_PARITY_ODD : SP_PARITY_NONE;
  // XON/XOFF is handled by the protocol code (see termios_transport.cpp), so the port passes it through.
  const sp_flowcontrol flow = settings.flow == FlowControl::RtsCts ? SP_FLOWCONTROL_RTSCTS : SP_FLOWCONTROL_NONE;
  if (sp_set_baudrate(port, settings.baud) != SP_OK || sp_set_bits(port, settings.data_bits) != SP_OK ||
      sp_set_parity(port, parity) != SP_OK || sp_set_stopbits(port, settings.stop_bits) != SP_OK ||
      sp_set_flowcontrol(port, flow) != SP_OK) {
    const std::string why = last_error();
    sp_close(port);
    sp_free_port(port);
    return {nullptr, device + ": cannot apply line settings: " + why};
  }
  int fd = -1;
  sp_get_port_handle(port, &fd);
  sp_flush(port, SP_BUF_BOTH);
  const std::string description = "serial " + device + " " + std::to_string(settings.baud) + " " +
                                  std::to_string(settings.data_bits) + settings.parity +
                                  std::to_string(settings.stop_bits) + " " + to_string(settings.flow);
  return {std::make_unique<SerialportTransport>(port, fd, description, settings.baud), ""};
}

}  // namespace lastcut::drivers
