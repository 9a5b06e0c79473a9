#pragma once
// The broker address of [status] mqtt_url: mqtt://HOST[:PORT] (plain TCP, port 1883 by default)
// or mqtts://HOST[:PORT] (TLS, 8883). HOST is a name, an IPv4 address or [IPv6]. Nothing else is
// accepted (no path, no user:password@ - the credentials have their own keys), so a typo is
// refused at load time instead of becoming a broker that is never reached.
#include <optional>
#include <string>

namespace lastcut::daemon {

struct MqttAddress {
  std::string host;  // without the brackets of an IPv6 literal
  int port = 1883;
  bool tls = false;
};

// The address, or nullopt with `why` set to a short reason ("the port must be 1 .. 65535").
std::optional<MqttAddress> parse_mqtt_url(const std::string& url, std::string& why);

// A topic level (station or cutter name) must be non-empty and free of '/', '+', '#' and NUL,
// which MQTT reserves; "" when usable, else why not.
std::string topic_level_problem(const std::string& level);

}  // namespace lastcut::daemon
