#pragma once
// The generated lasts that the orientation and segmentation tests are parameterised over: an EU size,
// a foot and a seed, named "EU42Left" in the test list.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "engine/core/foot_side.hpp"

namespace lastcut::test {

struct LastCase {
  int eu_size;
  FootSide side;
  std::uint64_t seed;
};

inline std::string last_case_name(const testing::TestParamInfo<LastCase>& info) {
  return "EU" + std::to_string(info.param.eu_size) + (info.param.side == FootSide::Left ? "Left" : "Right");
}

}  // namespace lastcut::test
