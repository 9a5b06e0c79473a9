#include "daemon/config/mqtt_url.hpp"

#include <cctype>

namespace lastcut::daemon {

std::optional<MqttAddress> parse_mqtt_url(const std::string& url, std::string& why) {
  MqttAddress address;
  std::string rest;
  if (url.rfind("mqtt://", 0) == 0) {
    rest = url.substr(7);
  } else if (url.rfind("mqtts://", 0) == 0) {
    rest = url.substr(8);
    address.tls = true;
    address.port = 8883;
  } else {
    why = "must start with mqtt:// or mqtts://";
    return std::nullopt;
  }
  if (rest.find_first_of("/?#@") != std::string::npos) {
    why = "only HOST[:PORT] may follow the scheme (no path, no user@; use username/password)";
    return std::nullopt;
  }
  std::string port_text;
  if (!rest.empty() && rest.front() == '[') {
    const auto close = rest.find(']');
    if (close == std::string::npos) {
      why = "an IPv6 address needs its closing ]";
      return std::nullopt;
    }
    address.host = rest.substr(1, close - 1);
    const std::string after = rest.substr(close + 1);
    if (!after.empty()) {
      if (after.front() != ':') {
        why = "only :PORT may follow an IPv6 address";
        return std::nullopt;
      }
      port_text = after.substr(1);
      if (port_text.empty()) port_text = "-";
    }
  } else {
    const auto colon = rest.find(':');
    address.host = rest.substr(0, colon);
    if (colon != std::string::npos) port_text = rest.substr(colon + 1).empty() ? "-" : rest.substr(colon + 1);
  }
  if (address.host.empty()) {
    why = "names no host";
    return std::nullopt;
  }
  for (const char c : address.host) {
    if (std::isspace(static_cast<unsigned char>(c)) || std::iscntrl(static_cast<unsigned char>(c))) {
      why = "the host must not contain spaces";
      return std::nullopt;
    }
  }
  if (!port_text.empty()) {
    bool digits = port_text.size() <= 5;
    for (const char c : port_text) digits = digits && std::isdigit(static_cast<unsigned char>(c));
    const int port = digits ? std::stoi(port_text) : 0;
    if (port < 1 || port > 65535) {
      why = "the port must be 1 .. 65535";
      return std::nullopt;
    }
    address.port = port;
  }
  return address;
}

std::string topic_level_problem(const std::string& level) {
  if (level.empty()) return "must not be empty";
  if (level.find_first_of(std::string("/+#\0", 4)) != std::string::npos) {
    return "must not contain /, + or # (MQTT topic characters)";
  }
  return {};
}

}  // namespace lastcut::daemon
