#pragma once
// StageClock: wall seconds per stage of a pipeline, in the order the stages ran, for the job
// report's "profile" (where did the 0.6 s go: reading, flattening or writing the pictures?).
//   StageClock clock;
//   read(...);    clock.lap("read");
//   flatten(...); clock.lap("medial: flatten");
#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace lastcut {

struct StageTime {
  std::string stage;
  double seconds = 0;
};

class StageClock {
 public:
  StageClock() : last_(std::chrono::steady_clock::now()) {}
  // Records the time since the previous lap (or the clock's start) under `stage`.
  void lap(std::string stage) {
    const auto now = std::chrono::steady_clock::now();
    stages_.push_back({std::move(stage), std::chrono::duration<double>(now - last_).count()});
    last_ = now;
  }
  const std::vector<StageTime>& stages() const { return stages_; }

 private:
  std::chrono::steady_clock::time_point last_;
  std::vector<StageTime> stages_;
};

}  // namespace lastcut
