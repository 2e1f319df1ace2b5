// JSON strings and numbers (see json.h).
#include "renderer/core/json.h"

#include <cmath>
#include <cstdio>

#include "renderer/core/printable.h"

namespace npr::json {

std::string string(const std::string& raw) {
  // Text from files (paths, names, warnings) escaped as messages are (\xNN for control
  // characters and invalid UTF-8), so the JSON is valid UTF-8 and a terminal showing it is safe.
  const std::string s = printableMessage(raw);
  std::string o = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"': o += "\\\""; break;
      case '\\': o += "\\\\"; break;
      case '\n': o += "\\n"; break;
      case '\t': o += "\\t"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          o += buf;
        } else {
          o += static_cast<char>(c);
        }
    }
  }
  return o + "\"";
}

std::string number(double v, const char* format) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace npr::json
