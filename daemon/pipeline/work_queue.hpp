#pragma once
// WorkQueue: a closable FIFO handed from the main loop to the compute workers. Holds job and
// batch ids only, never geometry, so the memory of a long queue stays small.
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>

namespace lastcut::daemon {

template <typename T>
class WorkQueue {
 public:
  void push(T value) {
    {
      std::lock_guard lock(mutex_);
      items_.push_back(std::move(value));
    }
    ready_.notify_one();
  }

  // Blocks until an item arrives or the queue is closed (then returns nullopt).
  std::optional<T> pop() {
    std::unique_lock lock(mutex_);
    ready_.wait(lock, [this] { return closed_ || !items_.empty(); });
    if (items_.empty()) return std::nullopt;
    T value = std::move(items_.front());
    items_.pop_front();
    return value;
  }

  // Wakes every waiter; pop() returns nullopt once the queue is empty.
  void close() {
    {
      std::lock_guard lock(mutex_);
      closed_ = true;
    }
    ready_.notify_all();
  }

  // Drops what is still queued (the spool keeps the jobs; recovery finds them at next start).
  void clear_and_close() {
    {
      std::lock_guard lock(mutex_);
      items_.clear();
      closed_ = true;
    }
    ready_.notify_all();
  }

  std::size_t size() const {
    std::lock_guard lock(mutex_);
    return items_.size();
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<T> items_;
  bool closed_ = false;
};

}  // namespace lastcut::daemon
