// Time spans in operator messages: never "0 s" for a fraction of a second, no ".000" noise.
#include <gtest/gtest.h>

#include <limits>

#include "drivers/seconds_text.hpp"

using lastcut::drivers::seconds_text;

TEST(SecondsText, FractionsOfASecondKeepTwoDigits) {
  EXPECT_EQ(seconds_text(0.25), "0.25 s");
  EXPECT_EQ(seconds_text(0.4), "0.4 s");
  EXPECT_EQ(seconds_text(2.5), "2.5 s");
}

TEST(SecondsText, WholeSecondsHaveNoDecimals) {
  EXPECT_EQ(seconds_text(2.0), "2 s");
  EXPECT_EQ(seconds_text(10.0), "10 s");
  EXPECT_EQ(seconds_text(30.4), "30 s");
  EXPECT_EQ(seconds_text(9.96), "10 s");
}

TEST(SecondsText, NonsenseStaysReadable) {
  EXPECT_EQ(seconds_text(-1.0), "0 s");
  EXPECT_EQ(seconds_text(std::numeric_limits<double>::quiet_NaN()), "0 s");
}
