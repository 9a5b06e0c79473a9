// TCP backend: non-blocking connect with a timeout, TCP_NODELAY (grbl acks are tiny), then FdTransport.
#include "drivers/transport/tcp_transport.hpp"

#include <cerrno>
#include <cstring>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include "drivers/transport/fd_transport.hpp"

namespace lastcut::drivers {

bool split_host_port(const std::string& host_port, std::string& host, int& port) {
  const auto colon = host_port.rfind(':');
  if (colon == std::string::npos || colon == 0) return false;
  host = host_port.substr(0, colon);
  const std::string digits = host_port.substr(colon + 1);
  if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos) return false;
  port = std::stoi(digits);
  return port >= 1 && port <= 65535;
}

OpenResult open_tcp_transport(const std::string& host_port, double timeout_s) {
  std::string host;
  int port = 0;
  if (!split_host_port(host_port, host, port)) return {nullptr, "bad TCP address '" + host_port + "' (want host:port)"};
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (const int rc = ::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found); rc != 0) {
    return {nullptr, "cannot resolve " + host + ": " + ::gai_strerror(rc)};
  }
  std::string last_error = "no address";
  for (addrinfo* a = found; a != nullptr; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    int rc = ::connect(fd, a->ai_addr, a->ai_addrlen);
    if (rc != 0 && errno == EINPROGRESS) {
      pollfd pfd{fd, POLLOUT, 0};
      rc = ::poll(&pfd, 1, static_cast<int>(timeout_s * 1000));
      if (rc == 0) {
        errno = ETIMEDOUT;
        rc = -1;
      } else if (rc > 0) {
        int so_error = 0;
        socklen_t len = sizeof so_error;
        ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &so_error, &len);
        errno = so_error;
        rc = so_error == 0 ? 0 : -1;
      }
    }
    if (rc == 0) {
      ::freeaddrinfo(found);
      int one = 1;
      ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
      return {std::make_unique<FdTransport>(fd, "tcp " + host_port, 0, false), ""};
    }
    last_error = std::strerror(errno);
    ::close(fd);
  }
  ::freeaddrinfo(found);
  return {nullptr, "cannot connect to " + host_port + ": " + last_error};
}

}  // namespace lastcut::drivers
