// What a file says is shown escaped: control characters and bytes that are not UTF-8 as \xNN,
// everything else (UTF-8 beyond ASCII included) as it is.
#include "harness/formats/printable.h"

#include <gtest/gtest.h>

namespace cc::harness {
namespace {

TEST(Printable, EscapesControlCharactersAndKeepsTheRest) {
  EXPECT_EQ(printable("plain text, 1 < 2"), "plain text, 1 < 2");
  EXPECT_EQ(printable(std::string_view("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(printable("\x1b[31mred\n\t\x7f"), "\\x1b[31mred\\x0a\\x09\\x7f");
  // The C1 controls (a terminal's CSI is U+009B) are escaped; U+00A0, just after them, is kept.
  EXPECT_EQ(printable("\xc2\x9b" "31m \xc2\x80 \xc2\x9f \xc2\xa0"), "\\xc2\\x9b" "31m \\xc2\\x80 \\xc2\\x9f \xc2\xa0");
}

TEST(Printable, KeepsWellFormedUtf8AndEscapesTheRest) {
  EXPECT_EQ(printable("caf\xc3\xa9 \xe2\x88\x9e \xf0\x9f\x99\x82"), "caf\xc3\xa9 \xe2\x88\x9e \xf0\x9f\x99\x82");
  EXPECT_EQ(printable("\xff"), "\\xff");
  EXPECT_EQ(printable("\xc3"), "\\xc3");                  // cut short
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");          // overlong
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
  EXPECT_EQ(printable("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // past U+10FFFF
  EXPECT_EQ(printable("\xef\xbb\xbf"), "\xef\xbb\xbf");    // a byte-order mark is a character
  // A right-to-left override (U+202E) and isolate (U+2067) reorder what follows: escaped; the
  // characters just outside their ranges (U+2029, U+202F, U+2065, U+206A) are kept.
  EXPECT_EQ(printable("a\xe2\x80\xae" "b\xe2\x81\xa7" "c"), "a\\xe2\\x80\\xae" "b\\xe2\\x81\\xa7" "c");
  EXPECT_EQ(printable("\xe2\x80\xa9\xe2\x80\xaf\xe2\x81\xa5\xe2\x81\xaa"), "\xe2\x80\xa9\xe2\x80\xaf\xe2\x81\xa5\xe2\x81\xaa");
}

}  // namespace
}  // namespace cc::harness
