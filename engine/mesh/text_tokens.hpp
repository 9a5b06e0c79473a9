#pragma once
// Whitespace-separated tokens of a text held in memory, for counting the records of ASCII mesh
// files (OFF, PLY) without converting them: line-by-line streams are far too slow on large scans.
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

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

  std::string_view text_;
  bool hash_comments_;
  size_t position_ = 0;
};

}  // namespace lastcut
