#pragma once
// Listing serial ports with their USB identity, so configuration can name a port stably
// ("usb:0403:6001:A10K3X" or a /dev/serial/by-id/ path) instead of /dev/ttyUSB0, which
// changes with plug order.
#include <string>
#include <vector>

namespace lastcut::drivers {

struct SerialPortInfo {
  std::string device;        // /dev/ttyUSB0
  std::string description;   // libserialport's description ("FT232R USB UART")
  bool usb = false;
  int usb_vid = 0, usb_pid = 0;
  std::string usb_serial, usb_manufacturer, usb_product;
  std::string by_id_path;    // /dev/serial/by-id/usb-FTDI_... when udev made one
  // "usb:0403:6001:A10K3X" (without the serial part when the adapter has none); empty if not USB.
  std::string stable_name() const;
};

// Every serial port libserialport can see. Empty list (not an error) on a machine without any.
std::vector<SerialPortInfo> list_serial_ports();

// Resolves "usb:VID:PID[:SERIAL]" (hex, case-insensitive) to one device path.
// Returns false with `error` set when none or more than one adapter matches.
bool resolve_usb_port(const std::string& spec, std::string& device, std::string& error);

}  // namespace lastcut::drivers
