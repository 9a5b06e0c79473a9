#pragma once
// Whitespace-separated tokens of a text held in memory, for counting the records of ASCII mesh
// files (OFF, PLY) without converting them: line-by-line streams are far too slow on large scans.
#include <cstdlib>
#include <string>
#include <string_view>

namespace lastcut {

class TextTokens {
 public:
  // `text` must outlive the tokens. With hash_comments, '#' to the end of the line is skipped (OFF).
  TextTokens(std::string_view text, bool hash_comments) : text_(text), hash_comments_(hash_comments) {}

  // The next token; empty at the end of the text.
  std::string_view next() {
    while (position_ < text_.size()) {
      const char c = text_[position_];
      if (hash_comments_ && c == '#') {
        skip_line();
      } else if (is_space(c)) {
        ++position_;
      } else {
        break;
      }
    }
    const size_t start = position_;
    while (position_ < text_.size() && !is_space(text_[position_])) ++position_;
    return text_.substr(start, position_ - start);
  }
  // Skips what is left of the current line (e.g. optional per-face colours).
  void skip_line() {
    while (position_ < text_.size() && text_[position_] != '\n') ++position_;
  }
  void seek(size_t position) { position_ = position; }
  // The text from here to the end of the line (without the '\n'); moves past it.
  std::string_view rest_of_line() {
    const size_t start = position_;
    skip_line();
    return text_.substr(start, position_ - start);
  }

  // True when strtod reads `token` as a whole ("1.5", "-2e3"), so a stream reading numbers one
  // after the other ends where this token ends.
  static bool is_number(std::string_view token) {
    if (token.empty() || token.size() > 64) return false;
    const std::string text(token);
    char* end = nullptr;
    std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size();
  }
  // True for a plain count: digits only, at most `limit`.
  static bool is_count(std::string_view token, long long limit) {
    long long value = 0;
    return read_count(token, limit, value);
  }
  // As is_count, and the count into `value`.
  static bool read_count(std::string_view token, long long limit, long long& value) {
    if (token.empty() || token.size() > 18) return false;
    value = 0;
    for (char c : token) {
      if (c < '0' || c > '9') return false;
      value = value * 10 + (c - '0');
    }
    return value <= limit;
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

  std::string_view text_;
  bool hash_comments_;
  size_t position_ = 0;
};

}  // namespace lastcut
