#pragma once
// TCP backend for network plotters and cutters ("tcp://host:port", raw socket, e.g. port 9100).
#include <string>

#include "drivers/transport/transport.hpp"

namespace lastcut::drivers {

// host_port: "127.0.0.1:9100" (the part after tcp://). Connects within timeout_s.
OpenResult open_tcp_transport(const std::string& host_port, double timeout_s);

// Splits "host:port"; false when the port is missing or not 1..65535.
bool split_host_port(const std::string& host_port, std::string& host, int& port);

}  // namespace lastcut::drivers
