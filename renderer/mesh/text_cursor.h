// A cursor over a text file held in memory, for the line- and token-based mesh formats (PLY
// ascii, OFF): numbers through std::from_chars (no locale, no allocation), never reading past
// the end, and counting lines so every message can name one.
#pragma once

#include <charconv>
#include <cstddef>
#include <limits>
#include <string_view>
#include <system_error>

namespace npr {

class TextCursor {
 public:
  TextCursor(const char* begin, const char* end) : p_(begin), end_(end) {}

  const char* position() const { return p_; }
  std::size_t line() const { return line_; }
  bool atEnd() const { return p_ >= end_; }

  // Skips spaces, tabs and carriage returns; not newlines.
  void skipBlanks() {
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\f' || *p_ == '\v')) ++p_;
  }
  // Skips whitespace, newlines and `#` comments up to the next token.
  void skipSpaceAndComments() {
    while (p_ < end_) {
      skipBlanks();
      if (p_ < end_ && *p_ == '#') skipLine();
      else if (p_ < end_ && *p_ == '\n') { ++p_; ++line_; }
      else return;
    }
  }
  void skipLine() {
    while (p_ < end_ && *p_ != '\n') ++p_;
    if (p_ < end_) { ++p_; ++line_; }
  }
  bool atEndOfLine() {
    skipBlanks();
    return p_ >= end_ || *p_ == '\n' || *p_ == '#';
  }
  std::string_view token() {
    skipSpaceAndComments();
    const char* s = p_;
    while (p_ < end_ && !(*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n' || *p_ == '\f' || *p_ == '\v')) ++p_;
    return {s, static_cast<std::size_t>(p_ - s)};
  }
  // A number on the current line (false at the end of the line or on something else). An
  // out-of-range value reads as infinity, so the caller refuses it like any non-finite one.
  bool number(double& out) {
    skipBlanks();
    if (p_ < end_ && *p_ == '+') ++p_;
    auto [q, ec] = std::from_chars(p_, end_, out);
    if (ec == std::errc::result_out_of_range) {
      out = std::numeric_limits<double>::infinity();
    } else if (ec != std::errc()) {
      return false;
    }
    p_ = q;
    return true;
  }
  template <class Int>
  bool integer(Int& out) {
    skipBlanks();
    if (p_ < end_ && *p_ == '+') ++p_;
    auto [q, ec] = std::from_chars(p_, end_, out);
    if (ec != std::errc()) return false;
    p_ = q;
    return true;
  }

 private:
  const char* p_;
  const char* end_;
  std::size_t line_ = 1;
};

}  // namespace npr
