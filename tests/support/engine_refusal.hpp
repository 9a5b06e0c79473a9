#pragma once
// The message of the EngineError an action throws, for tests of refusals that compare it whole.
#include <string>

#include "engine/core/engine_error.hpp"

namespace lastcut::test {

// What `action` was refused with, or "accepted" (which no expected message equals) when it threw nothing.
template <typename Action>
std::string engine_refusal(Action&& action) {
  try {
    action();
  } catch (const EngineError& error) {
    return error.what();
  }
  return "accepted";
}

}  // namespace lastcut::test
