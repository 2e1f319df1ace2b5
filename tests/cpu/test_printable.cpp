// CPU tier: the one escaping every message goes through (renderer/core/printable.h).
#include <gtest/gtest.h>

#include "renderer/core/printable.h"

namespace npr {
namespace {

TEST(Printable, ControlBytesAndInvalidUtf8AreEscaped) {
  EXPECT_EQ(printable(std::string("a\x1b[2Jb\x07\r", 8)), "a\\x1b[2Jb\\x07\\x0d");
  EXPECT_EQ(printable(std::string("nul\0end", 7)), "nul\\x00end");
  EXPECT_EQ(printable("\x7f"), "\\x7f");
  EXPECT_EQ(printable("\xff\xfe"), "\\xff\\xfe");              // never UTF-8
  EXPECT_EQ(printable("\xc3"), "\\xc3");                        // a sequence cut short
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");               // an overlong '/'
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");      // a UTF-16 surrogate
  EXPECT_EQ(printable("\xc2\x9b" "31m"), "\\xc2\\x9b31m");      // U+009B, the 8-bit CSI
}

TEST(Printable, ValidUtf8IsKept) {
  EXPECT_EQ(printable("mod\xc3\xa8le.obj"), "mod\xc3\xa8le.obj");
  EXPECT_EQ(printable("\xe6\xa8\xa1\xe5\x9e\x8b.ply"), "\xe6\xa8\xa1\xe5\x9e\x8b.ply");
  EXPECT_EQ(printable("\xf0\x9f\x90\x87"), "\xf0\x9f\x90\x87");
}

TEST(Printable, QuotesAreCutMessagesAreNot) {
  const std::string longText(200, 'x');
  EXPECT_EQ(printable(longText), std::string(80, 'x') + "...");
  EXPECT_EQ(printableMessage(longText), longText);
  EXPECT_EQ(printableMessage("line one\nline\ttwo"), "line one\nline\\x09two");
}

}  // namespace
}  // namespace npr
