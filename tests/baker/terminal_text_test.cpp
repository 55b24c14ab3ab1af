// Text from files is printed with its control characters escaped.
#include <gtest/gtest.h>

#include <string>

#include "data_formats/terminal_text.h"

namespace skybake {
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

// Quoted untrusted text: escaped, a NUL included, and cut after
// kMaxShownBytes at a character boundary with the whole length said.
TEST(TerminalText, ShownTextIsEscapedAndShortened) {
  EXPECT_EQ(shownText(std::string("1\0"
                                  "5",
                                  3)),
            "1\\x005");
  EXPECT_EQ(shownText(std::string(kMaxShownBytes, 'x')), std::string(kMaxShownBytes, 'x'));
  const std::string long_cell(60u << 20, '7');
  EXPECT_EQ(shownText(long_cell), std::string(kMaxShownBytes, '7') + "... (62914560 bytes)");
  // A two-byte character straddling the cut is left out whole.
  const std::string accents = std::string(kMaxShownBytes - 1, 'a') + "\xc3\xa9tail";
  EXPECT_EQ(shownText(accents),
            std::string(kMaxShownBytes - 1, 'a') + "... (" + std::to_string(accents.size()) + " bytes)");
}

}  // namespace
}  // namespace skybake
