// Text from a user's file or command line as it may be shown in a message: control characters
// and bytes outside printable ASCII written as \xNN, and long text cut, so a message never
// sends a file's raw bytes (escape sequences, NULs) to a terminal.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace npr {

inline std::string printable(std::string_view text, std::size_t maxChars = 80) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (out.size() >= maxChars) return out + "...";
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

}  // namespace npr
