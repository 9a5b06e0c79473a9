#pragma once
// The name GoogleTest gives a case run once per foot side ("Left", "Right" as to_string says).
#include <string>

#include <gtest/gtest.h>

#include "engine/core/foot_side.hpp"

namespace lastcut::test {

inline std::string side_name(const ::testing::TestParamInfo<FootSide>& param) { return std::string(to_string(param.param)); }

}  // namespace lastcut::test
