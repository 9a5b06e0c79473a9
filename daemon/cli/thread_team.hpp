#pragma once
// A fixed team of threads for NestOptions::run_parallel. The strip search hands over one batch of
// tasks per sweep, hundreds of times a second; starting and joining fresh std::threads for every
// batch cost more than some sweeps themselves. The team's threads start once and wait for the next
// batch. run() returns when every task of the batch is done; the caller's thread runs task 0.
// Used by `lastcut nest` and bench/nest/nest_bench (the engine itself starts no threads).
#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace lastcut {

class ThreadTeam {
 public:
  // helpers: threads besides the caller's (a batch of k tasks uses min(k - 1, helpers) of them;
  // tasks beyond helpers + 1 run on the caller's thread after its own).
  explicit ThreadTeam(size_t helpers) {
    for (size_t h = 0; h < helpers; ++h) threads_.emplace_back([this, h] { serve(h + 1); });
  }
  ~ThreadTeam() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (auto& t : threads_) t.join();
  }
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  void run(std::vector<std::function<void()>>& tasks) {
    if (tasks.empty()) return;
    const size_t handed = std::min(tasks.size() - 1, threads_.size());
    {
      std::lock_guard lock(mutex_);
      tasks_ = &tasks;
      handed_ = handed;
      pending_ = handed;
      ++generation_;
    }
    wake_.notify_all();
    tasks[0]();
    for (size_t t = handed + 1; t < tasks.size(); ++t) tasks[t]();
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    tasks_ = nullptr;
  }

  // As a NestOptions::run_parallel (the team must outlive the options' use).
  std::function<void(std::vector<std::function<void()>>&)> runner() {
    return [this](std::vector<std::function<void()>>& tasks) { run(tasks); };
  }

 private:
  void serve(size_t index) {
    size_t seen = 0;
    for (;;) {
      std::function<void()>* task = nullptr;
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
        if (stopping_) return;
        seen = generation_;
        if (index <= handed_) task = &(*tasks_)[index];
      }
      if (!task) continue;
      (*task)();
      std::lock_guard lock(mutex_);
      if (--pending_ == 0) done_.notify_one();
    }
  }

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::vector<std::function<void()>>* tasks_ = nullptr;
  size_t handed_ = 0, pending_ = 0, generation_ = 0;
  bool stopping_ = false;
};

}  // namespace lastcut
