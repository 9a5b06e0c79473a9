// Replays a fuzz target's corpus in the normal (gcc) build: every file of the target's seed
// corpus folder (tests/fuzz/corpus/<target>/, including the regression-* inputs of fixed crashes)
// is fed once to LLVMFuzzerTestOneInput. So the inputs that once crashed a parser stay fixed, and
// under -DLASTCUT_SANITIZE=ON (label `sanitize`) they run again under ASan+UBSan, without clang.
// The test fails when the folder is missing or empty, so it cannot pass vacuously.
// Compiled once per target with LASTCUT_FUZZ_CORPUS (the folder) and LASTCUT_FUZZ_TEST (test name).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

std::vector<uint8_t> read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(FuzzReplay, LASTCUT_FUZZ_TEST) {
  const std::filesystem::path corpus = LASTCUT_FUZZ_CORPUS;
  ASSERT_TRUE(std::filesystem::is_directory(corpus)) << "no corpus folder " << corpus;
  std::vector<std::filesystem::path> inputs;
  for (const auto& entry : std::filesystem::directory_iterator(corpus))
    if (entry.is_regular_file()) inputs.push_back(entry.path());
  ASSERT_FALSE(inputs.empty()) << "empty corpus folder " << corpus;
  std::sort(inputs.begin(), inputs.end());
  for (const auto& input : inputs) {
    SCOPED_TRACE(input.filename().string());
    const std::vector<uint8_t> bytes = read_bytes(input);
    // libFuzzer calls with a null pointer for the empty input; do the same.
    EXPECT_EQ(LLVMFuzzerTestOneInput(bytes.empty() ? nullptr : bytes.data(), bytes.size()), 0);
  }
  std::printf("replayed %zu inputs from %s\n", inputs.size(), corpus.string().c_str());
}

}  // namespace
