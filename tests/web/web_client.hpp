#pragma once
// What the operator page's tests send: exact bytes over a plain TCP socket to 127.0.0.1 (so a
// hostile request is sent as written, not as an HTTP library would tidy it), and a reader of the
// live event stream that notes when each event arrived.
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace lastcut::web_testing {

struct HttpAnswer {
  int status = 0;        // 0: the server closed or sent no status line
  std::string headers;   // the head, status line included
  std::string body;
};

// Sends `request` as is and reads the answer until the server closes or `timeout_s` passes.
HttpAnswer raw_http(int port, const std::string& request, double timeout_s = 10);
// A GET or POST with "Connection: close", optional extra header lines ("Name: value\r\n").
HttpAnswer http(int port, const std::string& method, const std::string& target, const std::string& extra_headers = "",
                const std::string& body = "");

// Follows GET /api/events on its own thread until stopped.
class EventReader {
 public:
  struct Event {
    std::string kind;  // "job", "cutter", "resync"
    std::string data;  // the JSON text
    std::chrono::steady_clock::time_point arrived;
  };
  explicit EventReader(int port);
  ~EventReader();
  std::vector<Event> events() const;
  bool connected() const;

 private:
  void run(int port);
  mutable std::mutex mutex_;
  std::vector<Event> events_;
  bool connected_ = false;
  int fd_ = -1;
  std::thread thread_;
};

}  // namespace lastcut::web_testing
