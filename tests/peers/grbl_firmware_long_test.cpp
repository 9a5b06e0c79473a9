// The real grbl 1.1h firmware runs a 3,000-move job to the end, every motion line one block in
// its block log (none lost, none twice). Label firmware-slow: see tests/peers/CMakeLists.txt.
#include <gtest/gtest.h>

#include "tests/peers/firmware_peer.hpp"

namespace lastcut::drivers {
namespace {

using testing::Firmware;
using testing::moves;
using testing::motion_lines;

TEST(GrblFirmware, ThreeThousandMoveJobExecutesEveryBlock) {
  Firmware firmware;
  ASSERT_TRUE(firmware.process->ready()) << firmware.process->ready_line();
  const std::string program = moves(3000);
  const SendResult result = firmware.send(program);
  ASSERT_EQ(result.outcome, SendOutcome::Done) << result.reason;
  const auto blocks = firmware.blocks();
  EXPECT_EQ(static_cast<int>(blocks.size()), motion_lines(program)) << "a motion line was lost or duplicated";
  ASSERT_FALSE(blocks.empty());
  EXPECT_EQ(blocks.back().substr(0, 9), "0, 0, 0, ") << "the last block must end at home: " << blocks.back();
}

}  // namespace
}  // namespace lastcut::drivers
