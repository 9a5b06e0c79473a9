// decimal_text must write what printf("%.*f") writes (the files it replaced printf in are read by
// other tools), whatever the value: printf is the oracle.
#include "engine/core/decimal_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace lastcut {
namespace {

std::string printf_fixed(double value, int decimals) {
  char text[400];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

TEST(DecimalText, WritesWhatPrintfWritesForRandomValues) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-12, 12);
  for (int i = 0; i < 200000; ++i) {
    const double value = mantissa(random) * std::pow(10.0, exponent(random));
    for (int decimals : {0, 2, 3, 6}) ASSERT_EQ(fixed_text(value, decimals), printf_fixed(value, decimals)) << value;
  }
}

TEST(DecimalText, WritesWhatPrintfWritesForEdgeValues) {
  for (double value : {0.0, -0.0, 0.5, 1.5, 2.5, -2.5, 0.125, 1e-7, -1e-7, 0.0000005, 1234567.0000005,
                       std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min()})
    for (int decimals : {0, 3, 6}) EXPECT_EQ(fixed_text(value, decimals), printf_fixed(value, decimals)) << value;
}

TEST(DecimalText, AppendsIntegers) {
  std::string text = "f";
  append_integer(text, 42);
  append_integer(text, -7);
  EXPECT_EQ(text, "f42-7");
}

}  // namespace
}  // namespace lastcut
