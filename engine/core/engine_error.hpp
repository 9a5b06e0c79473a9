#pragma once
// EngineError: the one exception type the engine throws for bad input or a failed step.
// Its message is one line an operator can read ("truncated binary STL: 120 of 5000 triangles").
// The daemon and the command line catch it per job and turn it into a failed job with that reason.
#include <stdexcept>
#include <string>

namespace lastcut {

class EngineError : public std::runtime_error {
 public:
  explicit EngineError(const std::string& one_line_reason);
};

}  // namespace lastcut
