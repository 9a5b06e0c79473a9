// The page's gates: which token a request carries, and how many requests one address may make.
#include <gtest/gtest.h>

#include "daemon/web/web_guard.hpp"

namespace lastcut::daemon {
namespace {

const std::map<std::string, std::string> kTokens = {{"anna", "0123456789abcdef-anna"}, {"ben", "fedcba9876543210-ben"}};

TEST(WebGuard, TheTokenNamesWhoActs) {
  EXPECT_EQ(token_name(kTokens, "Bearer 0123456789abcdef-anna"), "anna");
  EXPECT_EQ(token_name(kTokens, "Bearer fedcba9876543210-ben"), "ben");
}

TEST(WebGuard, AnythingElseIsNobody) {
  EXPECT_EQ(token_name(kTokens, ""), "");
  EXPECT_EQ(token_name(kTokens, "Bearer "), "");
  EXPECT_EQ(token_name(kTokens, "0123456789abcdef-anna"), "");           // no scheme
  EXPECT_EQ(token_name(kTokens, "Basic 0123456789abcdef-anna"), "");
  EXPECT_EQ(token_name(kTokens, "Bearer 0123456789abcdef-ann"), "");     // one character short
  EXPECT_EQ(token_name(kTokens, "Bearer 0123456789abcdef-annaX"), "");   // one too many
  EXPECT_EQ(token_name(kTokens, "Bearer 0123456789abcdef-anne"), "");
  EXPECT_EQ(token_name({}, "Bearer 0123456789abcdef-anna"), "");
}

TEST(WebGuard, RateLimiterAllowsABurstThenTheRate) {
  RateLimiter limiter(10);
  const auto start = std::chrono::steady_clock::now();
  int allowed = 0;
  for (int i = 0; i < 100; ++i) allowed += limiter.allow("10.0.0.1", start);
  EXPECT_EQ(allowed, 20);  // a burst of twice the rate
  EXPECT_TRUE(limiter.allow("10.0.0.2", start)) << "another address has its own bucket";
  EXPECT_FALSE(limiter.allow("10.0.0.1", start + std::chrono::milliseconds(50)));
  EXPECT_TRUE(limiter.allow("10.0.0.1", start + std::chrono::milliseconds(150)));  // 1.5 requests refilled
}

}  // namespace
}  // namespace lastcut::daemon
