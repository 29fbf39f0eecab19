#include "report/html_text.h"

#include <gtest/gtest.h>

namespace arbc::report {
namespace {

TEST(HtmlTextTest, EscapesTheFiveSpecialCharacters) {
  EXPECT_EQ(html_escape("<script>alert('x' & \"y\")</script>"),
            "&lt;script&gt;alert(&#39;x&#39; &amp; &quot;y&quot;)&lt;/script&gt;");
  EXPECT_EQ(html_escape("e_taken"), "e_taken");
  EXPECT_EQ(html_escape("caf\xC3\xA9 \xE2\x86\x92"), "caf\xC3\xA9 \xE2\x86\x92");  // UTF-8 kept
}

TEST(HtmlTextTest, ControlCharactersBecomeReplacementCharacters) {
  EXPECT_EQ(html_escape(std::string("a\0b\x01\tc\n", 7)),
            "a\xEF\xBF\xBD"
            "b\xEF\xBF\xBD\tc\n");
}

TEST(HtmlTextTest, NumberFormats) {
  EXPECT_EQ(seconds_text(12.3), "12.300");
  EXPECT_EQ(seconds_text(0), "0.000");
  // A 500 ms run's 300 bins are 1.67 ms wide, not "0.002 s".
  EXPECT_EQ(span_text(0.5 / 300), "1.67 ms");
  EXPECT_EQ(span_text(9.7 / 300), "32.3 ms");
  EXPECT_EQ(span_text(36), "36.000 s");
  EXPECT_EQ(coordinate(240), "240");
  EXPECT_EQ(coordinate(12.34), "12.3");
  EXPECT_EQ(coordinate(-0.01), "0");
  EXPECT_EQ(coordinate(3.96), "4");
}

}  // namespace
}  // namespace arbc::report
