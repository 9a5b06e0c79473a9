// Durable writes of a bare file name (as `lastcut toolpath -o cut.nc` passes it) go into the
// working folder (the other durable-write tests are in tests/daemon/spool_test.cpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/core/durable_file.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

std::string read_all(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(DurableFile, ABareFileNameIsWrittenIntoTheWorkingFolder) {
  const lastcut::test::TempDir scratch("durable");
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(scratch.path());
  const Status status = write_file_durably("cut.nc", "G0 X2\n");
  std::filesystem::current_path(previous);
  ASSERT_TRUE(status) << status.error();
  EXPECT_EQ(read_all(scratch / "cut.nc"), "G0 X2\n");
}

}  // namespace
}  // namespace lastcut
