#pragma once
// Status and Result<T>: what daemon and driver operations return instead of throwing.
// A failure carries one line an operator can act on ("cannot write batch.json: No space left on
// device"). Both are [[nodiscard]]: dropping a failure on the floor is a compile-time warning, so
// every error is either handled, passed up, or logged on purpose.
// The engine itself throws EngineError (engine_error.hpp); the daemon turns those into Status.
#include <optional>
#include <string>
#include <utility>

namespace lastcut {

class [[nodiscard]] Status {
 public:
  static Status success() { return Status(); }
  static Status failure(std::string one_line_reason) { return Status(std::move(one_line_reason)); }

  bool ok() const { return !failed_; }
  explicit operator bool() const { return ok(); }
  // Empty when ok.
  const std::string& error() const { return error_; }

  // The same failure with `context` in front ("molds made but not saved: " + error).
  Status with_context(const std::string& context) const { return ok() ? *this : failure(context + error_); }

 private:
  Status() = default;
  explicit Status(std::string error) : failed_(true), error_(std::move(error)) {}
  bool failed_ = false;
  std::string error_;
};

// A value, or the reason there is none.
template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit, so `return value;` reads naturally
  Result(Status failure) : status_(std::move(failure)) {}

  bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  const std::string& error() const { return status_.error(); }
  const Status& status() const { return status_; }

  // Only when ok().
  T& value() { return *value_; }
  const T& value() const { return *value_; }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }
  T& operator*() { return *value_; }
  const T& operator*() const { return *value_; }

 private:
  std::optional<T> value_;
  Status status_ = Status::success();
};

}  // namespace lastcut
