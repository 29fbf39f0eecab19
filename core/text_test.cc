// core/join.h, core/quote.h, core/xml_text.h and core/time_text.h: the one join, the escaping
// routines for literals and for markup, and the one way a time is printed for people.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "core/join.h"
#include "core/quote.h"
#include "core/time_text.h"
#include "core/xml_text.h"

namespace arbc {
namespace {

TEST(Join, SeparatesItemsOfAnyRange) {
  std::vector<std::string> v = {"a", "b", "c"};
  EXPECT_EQ(join(v), "a, b, c");
  EXPECT_EQ(join(v, " | "), "a | b | c");
  EXPECT_EQ(join(std::set<std::string>{"y", "x"}), "x, y");
  EXPECT_EQ(join(std::vector<std::string>{}), "");
  EXPECT_EQ(join(std::vector<std::string>{"only"}), "only");
}

TEST(Join, LastSeparatorGoesBeforeTheLastItemOnly) {
  EXPECT_EQ(join(std::vector<std::string>{"a", "b", "c"}, ", ", " or "), "a, b or c");
  EXPECT_EQ(join(std::vector<std::string>{"a", "b"}, ", ", " or "), "a or b");
  EXPECT_EQ(join(std::vector<std::string>{"a"}, ", ", " or "), "a");
}

TEST(Quote, JsonEscapesControlBytesAndKeepsUtf8) {
  EXPECT_EQ(quoted("a\"b\\c\nd\re\tf", QuoteStyle::Json), "\"a\\\"b\\\\c\\nd\\re\\tf\"");
  EXPECT_EQ(quoted("\x01\x1f\x7f", QuoteStyle::Json), "\"\\u0001\\u001f\x7f\"");
  EXPECT_EQ(quoted("caf\xc3\xa9", QuoteStyle::Json), "\"caf\xc3\xa9\"");
  // Escapes first and last, plain runs between and none at all.
  EXPECT_EQ(quoted("\"plain run\n\nanother\\", QuoteStyle::Json),
            "\"\\\"plain run\\n\\nanother\\\\\"");
  EXPECT_EQ(quoted("", QuoteStyle::Json), "\"\"");
}

TEST(Quote, LuaKeepsTheTextAscii) {
  EXPECT_EQ(quoted("a\"b\\c\nd\re\tf", QuoteStyle::Lua), "\"a\\\"b\\\\c\\nd\\re\\tf\"");
  EXPECT_EQ(quoted("\x01\x7f\xc3\xa9", QuoteStyle::Lua), "\"\\001\\127\\195\\169\"");
}

TEST(Quote, DotEscapesOnlyQuotesAndBackslashes) {
  EXPECT_EQ(quoted("say \"hi\"\\\n", QuoteStyle::Dot), "\"say \\\"hi\\\"\\\\\n\"");
}

TEST(Quote, AppendsAfterWhatIsThere) {
  std::string out = "x=";
  append_quoted(out, "v", QuoteStyle::Json);
  EXPECT_EQ(out, "x=\"v\"");
}

TEST(XmlText, EscapesMarkupAndKeepsUtf8AndApostrophes) {
  EXPECT_EQ(xml_escaped("a<b> & \"c\" it's \xc3\xa9"),
            "a&lt;b&gt; &amp; &quot;c&quot; it's \xc3\xa9");
}

TEST(XmlText, CommentTextHasNoDoubleHyphenAndNoFinalHyphen) {
  EXPECT_EQ(xml_comment_text("arbc build --target yarp"), "arbc build - -target yarp");
  EXPECT_EQ(xml_comment_text("a ---> b"), "a - - -> b");
  EXPECT_EQ(xml_comment_text("ends-"), "ends- ");
  EXPECT_EQ(xml_comment_text("<a & b>"), "<a & b>");  // no entities in a comment
  EXPECT_EQ(xml_comment_text(std::string("a\x01"
                                         "b",
                                         3)),
            "a\xEF\xBF\xBD"
            "b");
}

TEST(XmlText, ControlCharactersXmlForbidsBecomeReplacementCharacters) {
  EXPECT_EQ(xml_escaped(std::string("a\x01"
                                    "b\0c\td\ne\rf",
                                    11)),
            "a\xEF\xBF\xBD"
            "b\xEF\xBF\xBD"
            "c\td\ne\rf");
}

TEST(TimeText, DropsBinaryNoiseAndTrailingZeros) {
  EXPECT_EQ(time_text(0.1 + 0.2), "0.3");
  EXPECT_EQ(time_text(2.9000000000000012), "2.9");
  EXPECT_EQ(time_text(1.25), "1.25");
  EXPECT_EQ(time_text(3.0), "3");
  EXPECT_EQ(time_text(0.0000016), "0.000002");  // to the microsecond
  EXPECT_EQ(time_text(-0.0000001), "0");
}

}  // namespace
}  // namespace arbc
