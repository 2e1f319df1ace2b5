// The one JSON writer for the command line's reports (--info, --palette-info): strings
// escaped per RFC 8259 (quotes, backslashes, control characters as \u00XX), numbers in a
// fixed printf format so reports are stable across runs.
#pragma once

#include <string>

namespace npr::json {

// `s` as a quoted JSON string.
std::string string(const std::string& s);
// `v` with printf format `format` ("%.6g" unless told); non-finite values become null, which
// JSON has instead of NaN and infinity.
std::string number(double v, const char* format = "%.6g");

}  // namespace npr::json
