// numlab::printable(): what reaches an error line from outside is one line of visible text.

#include <catch2/catch.hpp>

#include "numlab/printable_text.hpp"

using numlab::printable;

TEST_CASE("printable keeps plain text and well-formed visible UTF-8") {
  CHECK(printable("row 3: '1.5e3' is fine") == "row 3: '1.5e3' is fine");
  CHECK(printable("caf\xc3\xa9 \xe2\x88\x9a 2") == "caf\xc3\xa9 \xe2\x88\x9a 2");  // é and √
  CHECK(printable("\xf0\x9f\x93\x90") == "\xf0\x9f\x93\x90");                      // a four-byte character
}

TEST_CASE("printable quotes control bytes, so a message stays one line and cannot drive the terminal") {
  CHECK(printable("\x1b]0;owned\x07") == "\\x1b]0;owned\\x07");  // the escape that retitles a terminal
  CHECK(printable("a\nb\rc\td") == "a\\x0ab\\x0dc\\x09d");
  CHECK(printable(std::string_view("\0", 1)) == "\\x00");
  CHECK(printable("\x7f") == "\\x7f");
  CHECK(printable("\xc2\x9b") == "\\xc2\\x9b");  // C1 control CSI, encoded as UTF-8
}

TEST_CASE("printable quotes invisible marks and ill-formed UTF-8 byte by byte") {
  CHECK(printable("\xef\xbb\xbf" "1") == "\\xef\\xbb\\xbf1");        // byte-order mark
  CHECK(printable("\xe2\x80\xae" "abc") == "\\xe2\\x80\\xaeabc");    // right-to-left override
  CHECK(printable("\xc0\xaf") == "\\xc0\\xaf");                      // overlong '/'
  CHECK(printable("\xed\xa0\x80") == "\\xed\\xa0\\x80");             // a UTF-16 surrogate
  CHECK(printable("\xe2\x82") == "\\xe2\\x82");                      // cut short
  CHECK(printable("\xff\xfe") == "\\xff\\xfe");
}
