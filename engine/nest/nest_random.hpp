#pragma once
// Random numbers that are the same on every platform and standard library (the std
// distributions are implementation-defined): mt19937_64 plus our own mapping to [0, 1).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <random>

namespace lastcut::nest_detail {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  int below(int n) { return static_cast<int>(engine_() % static_cast<std::uint64_t>(n)); }  // [0, n)
  std::uint64_t next() { return engine_(); }

 private:
  std::mt19937_64 engine_;
};

// A stream seed for worker `worker` of round `round` (splitmix64 of the three).
inline std::uint64_t stream_seed(std::uint64_t seed, std::uint64_t round, std::uint64_t worker) {
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (round * 1000003ULL + worker + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// When the time budget runs out. The engine only reads the clock; it never sleeps or waits.
class Deadline {
 public:
  explicit Deadline(double seconds)
      : end_(std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                     std::chrono::duration<double>(seconds))) {}
  bool passed() const { return std::chrono::steady_clock::now() >= end_; }
  double seconds_left() const {
    return std::max(0.0, std::chrono::duration<double>(end_ - std::chrono::steady_clock::now()).count());
  }

 private:
  std::chrono::steady_clock::time_point end_;
};

}  // namespace lastcut::nest_detail
