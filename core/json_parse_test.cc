#include "core/json_parse.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

TEST(JsonParseTest, ValidTextParses) {
  nlohmann::json j;
  JsonParseError e;
  ASSERT_TRUE(parse_json(std::string_view("{\"t\": 1.5}"), &j, &e));
  EXPECT_EQ(j["t"], 1.5);
}

// The offending byte's line and column, and the library's text without its tags and its own
// position: "[json.exception.parse_error.101] parse error at line 2, column 3: ..." is not shown.
TEST(JsonParseTest, ASyntaxErrorHasItsPositionAndNoLibraryTags) {
  nlohmann::ordered_json j;
  JsonParseError e;
  ASSERT_FALSE(parse_json(std::string_view("{\"a\": 1,\n  b: 2}"), &j, &e));
  EXPECT_EQ(e.line, 2u);
  EXPECT_EQ(e.column, 3u);
  EXPECT_EQ(e.detail.find("json.exception"), std::string::npos) << e.detail;
  EXPECT_EQ(e.detail.find("parse error"), std::string::npos) << e.detail;
  EXPECT_EQ(e.detail.rfind("syntax error while parsing object key", 0), 0u) << e.detail;
}

// Columns count characters, as every diagnostic's do: "é" is one column, not two.
TEST(JsonParseTest, TheColumnCountsCharacters) {
  nlohmann::json j;
  JsonParseError e;
  ASSERT_FALSE(parse_json(std::string_view("{\"\xC3\xA9\": x}"), &j, &e));
  EXPECT_EQ(e.line, 1u);
  EXPECT_EQ(e.column, 7u);
}

TEST(JsonParseTest, EmptyTextIsAnErrorAtItsStart) {
  nlohmann::json j;
  JsonParseError e;
  ASSERT_FALSE(parse_json(std::string_view(""), &j, &e));
  EXPECT_EQ(e.line, 1u);
  EXPECT_EQ(e.column, 1u);
}

// The library names the literal but not its place; the error has it all the same.
TEST(JsonParseTest, ANumberBeyondADoubleIsAnErrorAtItsLiteral) {
  nlohmann::json j;
  JsonParseError e;
  ASSERT_FALSE(parse_json(std::string_view("{\"a\": 1,\n \"b\": [1e999]}"), &j, &e));
  EXPECT_EQ(e.line, 2u);
  EXPECT_EQ(e.column, 8u);
  EXPECT_EQ(e.detail, "number overflow parsing '1e999' (beyond the range of a double)");
}

// JSON the library would take, keeping the last of two values of one key without a word: an
// error at the second key that names the line (or, for one line of JSON lines, the column) of
// the first.
TEST(JsonParseTest, AKeyRepeatedInOneObjectIsAnErrorAtTheSecond) {
  nlohmann::json j;
  JsonParseError e;
  ASSERT_FALSE(parse_json(std::string_view("{\"t\": 1,\n \"v\": {\"x\": 1},\n \"t\": 2}"), &j, &e));
  EXPECT_EQ(e.line, 3u);
  EXPECT_EQ(e.column, 2u);
  EXPECT_EQ(e.first_line, 1u);
  EXPECT_EQ(e.first_column, 2u);
  EXPECT_EQ(json_error_message(e),
            "key \"t\" repeated in one object (the first is at line 1); JSON readers keep only "
            "the last value, so remove one of the two");
  EXPECT_NE(json_error_message(e, /*one_line=*/true).find("(the first is at column 2)"),
            std::string::npos);
  nlohmann::ordered_json ordered;
  EXPECT_FALSE(parse_json(std::string_view("{\"a\": 1, \"a\": 1}"), &ordered, &e));
  EXPECT_TRUE(parse_json(std::string_view("{\"a\": {\"b\": 1}, \"b\": {\"a\": 1}}"), &j, &e));
}

TEST(JsonParseTest, ASyntaxErrorSaysItIsNotJson) {
  nlohmann::json j;
  JsonParseError e;
  ASSERT_FALSE(parse_json(std::string_view("{\"a\": tru}"), &j, &e));
  EXPECT_EQ(json_error_message(e).rfind("not valid JSON: syntax error", 0), 0u);
}

}  // namespace
}  // namespace arbc
