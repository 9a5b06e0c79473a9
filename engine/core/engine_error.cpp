#include "engine/core/engine_error.hpp"

namespace lastcut {

EngineError::EngineError(const std::string& one_line_reason) : std::runtime_error(one_line_reason) {}

}  // namespace lastcut
