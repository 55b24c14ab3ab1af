// Text from files is printed with its control characters escaped.
#include <gtest/gtest.h>

#include "baker/cli/terminal_text.h"

namespace skybake::cli {
namespace {

TEST(TerminalText, EscapesControlCharactersAndKeepsOtherText) {
  EXPECT_EQ(terminalSafe("red\x1b[31mtext"), "red\\x1b[31mtext");
  EXPECT_EQ(terminalSafe("bell\a del\x7f"), "bell\\x07 del\\x7f");
  EXPECT_EQ(terminalSafe("caf\xc3\xa9 \xe2\x98\x80"), "caf\xc3\xa9 \xe2\x98\x80");  // é and a sun: printable
  EXPECT_EQ(terminalSafe("csi\xc2\x9b"
                         "31m"),
            "csi\\xc2\\x9b31m");                            // U+009B, the C1 CSI
  EXPECT_EQ(terminalSafe("bad\xff\xc3"), "bad\\xff\\xc3");  // not UTF-8
  EXPECT_EQ(terminalSafe("a\nb\tc"), "a\\x0ab\\x09c");
  EXPECT_EQ(terminalSafe("a\nb\tc", true), "a\nb\tc");
}

}  // namespace
}  // namespace skybake::cli
