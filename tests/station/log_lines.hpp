#pragma once
// The daemon's log while a test runs (an extra spdlog sink), to count the lines a change makes:
// the station logs a change of condition once, not once per try.
#include <algorithm>
#include <memory>
#include <sstream>
#include <string>

#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

namespace lastcut::daemon::testing {

class LogLines {
 public:
  LogLines() : sink_(std::make_shared<spdlog::sinks::ostream_sink_mt>(text_)) {
    sink_->set_pattern("%v");
    spdlog::default_logger()->sinks().push_back(sink_);
  }
  ~LogLines() {
    auto& sinks = spdlog::default_logger()->sinks();
    sinks.erase(std::remove(sinks.begin(), sinks.end(), sink_), sinks.end());
  }
  LogLines(const LogLines&) = delete;
  LogLines& operator=(const LogLines&) = delete;

  // How often `phrase` was logged.
  int count(const std::string& phrase) const {
    const std::string text = text_.str();
    int n = 0;
    for (auto at = text.find(phrase); at != std::string::npos; at = text.find(phrase, at + 1)) ++n;
    return n;
  }
  std::string text() const { return text_.str(); }

 private:
  std::ostringstream text_;
  std::shared_ptr<spdlog::sinks::ostream_sink_mt> sink_;
};

}  // namespace lastcut::daemon::testing
