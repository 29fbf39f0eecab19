// core/join.h and core/quote.h: the one join and the one escaping routine.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "core/join.h"
#include "core/quote.h"

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

}  // namespace
}  // namespace arbc
