#pragma once
// TextSink: builds a text file in memory and writes it out every ~1 MB. One write (and one printf
// per number) per line cost more than flattening a 100k-triangle half; see decimal_text.hpp.
//   std::ofstream out(path, std::ios::binary);
//   { TextSink sink(out); sink.text() += "v "; append_fixed(sink.text(), x, 6); sink.end_line(); }
//   // then check `out` (the last flush happens when the sink goes out of scope)
#include <fstream>
#include <string>

namespace lastcut {

class TextSink {
 public:
  explicit TextSink(std::ofstream& out) : out_(out) { text_.reserve(kFlushBytes + 256); }
  ~TextSink() { flush(); }
  TextSink(const TextSink&) = delete;
  TextSink& operator=(const TextSink&) = delete;

  // The line being built; append to it, then end_line().
  std::string& text() { return text_; }
  void end_line() {
    text_ += '\n';
    if (text_.size() >= kFlushBytes) flush();
  }
  void flush() {
    out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
    text_.clear();
  }

 private:
  static constexpr size_t kFlushBytes = 1 << 20;
  std::ofstream& out_;
  std::string text_;
};

}  // namespace lastcut
