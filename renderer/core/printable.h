// Text from a user's file, path or command line as it may be shown in a message: control
// characters (C0, DEL, C1) and bytes that are not valid UTF-8 written as \xNN, so a message
// never sends a file's raw bytes (escape sequences, NULs, a terminal's 8-bit CSI) to a
// terminal. Valid UTF-8 (a path named in French or Japanese) is kept as it is.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace npr {

// One quoted piece of text, cut after `maxChars` bytes of output ("...").
std::string printable(std::string_view text, std::size_t maxChars = 80);

// A whole message at the point it is printed (stderr, the window's notes): the same escaping,
// never cut, line breaks kept (messages such as a device list span lines).
std::string printableMessage(std::string_view message);

}  // namespace npr
