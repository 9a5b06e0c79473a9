#pragma once
// The operator page's two gates before any handler runs: who may act (a token from [web.tokens],
// sent as "Authorization: Bearer SECRET", never a cookie, so no other site can make a browser act)
// and how fast one address may ask (a token bucket per client address).
#include <chrono>
#include <map>
#include <mutex>
#include <string>

namespace lastcut::daemon {

// The name of the token whose secret `authorization` carries ("Bearer SECRET"), or "" when it
// carries none of them. Every secret is compared in full whatever the input, so the time taken
// does not tell how much of a guess was right.
std::string token_name(const std::map<std::string, std::string>& tokens, const std::string& authorization);

// Allows `per_second` requests per address on average, bursts up to twice that.
class RateLimiter {
 public:
  explicit RateLimiter(int per_second) : per_second_(per_second) {}
  bool allow(const std::string& address, std::chrono::steady_clock::time_point now);

 private:
  struct Bucket {
    double tokens = 0;
    std::chrono::steady_clock::time_point last;
  };
  const int per_second_;
  std::mutex mutex_;
  std::map<std::string, Bucket> buckets_;
  std::chrono::steady_clock::time_point last_sweep_{};
};

}  // namespace lastcut::daemon
