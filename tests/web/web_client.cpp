// raw_http, http and EventReader (web_client.hpp), on plain POSIX sockets.
#include "tests/web/web_client.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>

namespace lastcut::web_testing {
namespace {

int connect_loopback(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (fd >= 0 && ::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) return fd;
  if (fd >= 0) ::close(fd);
  return -1;
}

HttpAnswer parse_answer(const std::string& bytes) {
  HttpAnswer answer;
  const std::size_t head_end = bytes.find("\r\n\r\n");
  answer.headers = bytes.substr(0, head_end);
  if (head_end != std::string::npos) answer.body = bytes.substr(head_end + 4);
  if (bytes.rfind("HTTP/1.", 0) == 0 && bytes.size() > 12) answer.status = std::atoi(bytes.c_str() + 9);
  return answer;
}

}  // namespace

HttpAnswer raw_http(int port, const std::string& request, double timeout_s) {
  const int fd = connect_loopback(port);
  if (fd < 0) return {};
  for (std::size_t sent = 0; sent < request.size();) {
    const ssize_t n = ::send(fd, request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) break;  // the server may answer (413) and close before it has read everything
    sent += static_cast<std::size_t>(n);
  }
  std::string bytes;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  char buffer[8192];
  while (std::chrono::steady_clock::now() < deadline) {
    pollfd wait{fd, POLLIN, 0};
    if (::poll(&wait, 1, 100) <= 0) continue;
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return parse_answer(bytes);
}

HttpAnswer http(int port, const std::string& method, const std::string& target, const std::string& extra_headers,
                const std::string& body) {
  std::string request = method + " " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n" + extra_headers;
  if (method == "POST") request += "Content-Length: " + std::to_string(body.size()) + "\r\n";
  return raw_http(port, request + "\r\n" + body);
}

EventReader::EventReader(int port) : thread_([this, port] { run(port); }) {}

EventReader::~EventReader() {
  {
    std::lock_guard lock(mutex_);
    if (fd_ >= 0) ::shutdown(fd_, SHUT_RDWR);
    fd_ = -2;  // tells run() to stop
  }
  thread_.join();
}

std::vector<EventReader::Event> EventReader::events() const {
  std::lock_guard lock(mutex_);
  return events_;
}

bool EventReader::connected() const {
  std::lock_guard lock(mutex_);
  return connected_;
}

void EventReader::run(int port) {
  const int fd = connect_loopback(port);
  {
    std::lock_guard lock(mutex_);
    if (fd_ == -2 || fd < 0) {
      if (fd >= 0) ::close(fd);
      return;
    }
    fd_ = fd;
  }
  const std::string request = "GET /api/events HTTP/1.1\r\nHost: 127.0.0.1\r\nAccept: text/event-stream\r\n\r\n";
  ::send(fd, request.data(), request.size(), MSG_NOSIGNAL);
  std::string pending;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    const auto now = std::chrono::steady_clock::now();
    pending.append(buffer, static_cast<std::size_t>(n));
    std::lock_guard lock(mutex_);
    if (pending.find("200 OK") != std::string::npos) connected_ = true;
    // Chunk sizes sit on lines of their own between the frames; an event is its "event:" and
    // "data:" lines, which is all this reader looks at.
    for (std::size_t at; (at = pending.find("event: ")) != std::string::npos;) {
      const std::size_t data = pending.find("\ndata: ", at);
      const std::size_t end = data == std::string::npos ? data : pending.find('\n', data + 7);
      if (end == std::string::npos) break;
      events_.push_back({pending.substr(at + 7, data - at - 7), pending.substr(data + 7, end - data - 7), now});
      pending.erase(0, end + 1);
    }
  }
  std::lock_guard lock(mutex_);
  ::close(fd);
  fd_ = -1;
}

}  // namespace lastcut::web_testing
