// Serial port enumeration through libserialport, plus the /dev/serial/by-id links udev makes.
#include "drivers/transport/serial_ports.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <libserialport.h>

namespace lastcut::drivers {

namespace {

std::string text_or_empty(const char* text) { return text ? std::string(text) : std::string(); }

std::string hex4(int value) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "%04x", value & 0xffff);
  return buffer;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

std::string SerialPortInfo::stable_name() const {
  if (!usb) return {};
  std::string name = "usb:" + hex4(usb_vid) + ":" + hex4(usb_pid);
  if (!usb_serial.empty()) name += ":" + usb_serial;
  return name;
}

std::vector<SerialPortInfo> list_serial_ports() {
  std::vector<SerialPortInfo> ports;
  sp_port** list = nullptr;
  if (sp_list_ports(&list) != SP_OK) return ports;
  for (sp_port** p = list; *p != nullptr; ++p) {
    SerialPortInfo info;
    info.device = text_or_empty(sp_get_port_name(*p));
    info.description = text_or_empty(sp_get_port_description(*p));
    if (sp_get_port_transport(*p) == SP_TRANSPORT_USB) {
      info.usb = sp_get_port_usb_vid_pid(*p, &info.usb_vid, &info.usb_pid) == SP_OK;
      info.usb_serial = text_or_empty(sp_get_port_usb_serial(*p));
      info.usb_manufacturer = text_or_empty(sp_get_port_usb_manufacturer(*p));
      info.usb_product = text_or_empty(sp_get_port_usb_product(*p));
    }
    ports.push_back(std::move(info));
  }
  sp_free_port_list(list);

  std::error_code ec;
  const std::filesystem::path by_id = "/dev/serial/by-id";
  if (std::filesystem::is_directory(by_id, ec)) {
    for (const auto& entry : std::filesystem::directory_iterator(by_id, ec)) {
      const auto target = std::filesystem::canonical(entry.path(), ec);
      if (ec) continue;
      for (auto& port : ports) {
        if (port.device == target.string()) port.by_id_path = entry.path().string();
      }
    }
  }
  std::sort(ports.begin(), ports.end(), [](const auto& a, const auto& b) { return a.device < b.device; });
  return ports;
}

bool resolve_usb_port(const std::string& spec, std::string& device, std::string& error) {
  // usb:VID:PID[:SERIAL]
  std::vector<std::string> parts;
  size_t start = 0;
  while (true) {
    const size_t colon = spec.find(':', start);
    parts.push_back(spec.substr(start, colon == std::string::npos ? std::string::npos : colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  if (parts.size() < 3 || parts.size() > 4 || parts[0] != "usb" || parts[1].size() != 4 || parts[2].size() != 4) {
    error = "bad USB port name '" + spec + "' (want usb:VID:PID or usb:VID:PID:SERIAL, ids in hex like usb:0403:6001)";
    return false;
  }
  const std::string vid = lower(parts[1]), pid = lower(parts[2]);
  const std::string serial = parts.size() == 4 ? parts[3] : "";
  std::vector<std::string> matches;
  for (const auto& port : list_serial_ports()) {
    if (!port.usb || hex4(port.usb_vid) != vid || hex4(port.usb_pid) != pid) continue;
    if (!serial.empty() && port.usb_serial != serial) continue;
    matches.push_back(port.device);
  }
  if (matches.empty()) {
    error = "no USB serial adapter " + spec + " is plugged in (see `lastcut ports`)";
    return false;
  }
  if (matches.size() > 1) {
    error = std::to_string(matches.size()) + " adapters match " + spec + " (" + matches[0] + ", " + matches[1] +
            "...): add the serial number, usb:VID:PID:SERIAL";
    return false;
  }
  device = matches.front();
  return true;
}

}  // namespace lastcut::drivers
