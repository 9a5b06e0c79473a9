// token_name and RateLimiter (web_guard.hpp).
#include "daemon/web/web_guard.hpp"

#include <algorithm>

namespace lastcut::daemon {

std::string token_name(const std::map<std::string, std::string>& tokens, const std::string& authorization) {
  static const std::string kScheme = "Bearer ";
  if (authorization.size() <= kScheme.size() || authorization.compare(0, kScheme.size(), kScheme) != 0) return "";
  const std::string given = authorization.substr(kScheme.size());
  std::string found;
  for (const auto& [name, secret] : tokens) {
    unsigned difference = given.size() != secret.size() ? 1u : 0u;
    for (std::size_t i = 0; i < secret.size(); ++i)
      difference |= static_cast<unsigned char>(secret[i]) ^ static_cast<unsigned char>(i < given.size() ? given[i] : 0);
    if (difference == 0) found = name;
  }
  return found;
}

bool RateLimiter::allow(const std::string& address, std::chrono::steady_clock::time_point now) {
  std::lock_guard lock(mutex_);
  // Addresses quiet for a minute are forgotten, so a scan of many addresses cannot grow the map for good.
  if (now - last_sweep_ > std::chrono::seconds(60)) {
    std::erase_if(buckets_, [&](const auto& entry) { return now - entry.second.last > std::chrono::seconds(60); });
    last_sweep_ = now;
  }
  const double burst = 2.0 * per_second_;
  auto [it, added] = buckets_.try_emplace(address, Bucket{burst, now});
  Bucket& bucket = it->second;
  const double elapsed_s = std::chrono::duration<double>(now - bucket.last).count();
  bucket.tokens = std::min(burst, bucket.tokens + elapsed_s * per_second_);
  bucket.last = now;
  if (bucket.tokens < 1.0) return false;
  bucket.tokens -= 1.0;
  return true;
}

}  // namespace lastcut::daemon
