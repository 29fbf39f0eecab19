// Placing keys and values of JSON text by their path, as readers of JSON files place errors.
#include "core/json_place.h"

#include <gtest/gtest.h>

#include <string>

namespace arbc {
namespace {

// "line:column-line:column" of the span, or "none".
std::string where(std::string_view text, const std::vector<std::string>& path,
                  JsonPart part = JsonPart::Value) {
  std::optional<TextSpan> s = json_place(text, path, part);
  if (!s) return "none";
  return std::to_string(s->begin.line) + ":" + std::to_string(s->begin.column) + "-" +
         std::to_string(s->end.line) + ":" + std::to_string(s->end.column);
}

TEST(TextPositionTest, CountsLinesAndCharacters) {
  std::string_view text = "ab\n\xC2\xB5x\n";  // "µ" is two bytes, one column
  EXPECT_EQ(text_position(text, 0).line, 1);
  EXPECT_EQ(text_position(text, 0).column, 1);
  EXPECT_EQ(text_position(text, 2).column, 3);
  EXPECT_EQ(text_position(text, 3).line, 2);
  EXPECT_EQ(text_position(text, 3).column, 1);
  EXPECT_EQ(text_position(text, 5).column, 2);  // the x after the µ
  EXPECT_EQ(text_position(text, 99).line, 3);   // past the end: after the last character
}

TEST(JsonPlaceTest, PlacesKeysAndValuesAlongAPath) {
  std::string_view text =
      "{\n"
      "  \"domain\": 300,\n"
      "  \"topics\": {\"Base.cmd_vel\": \"/cmd_vel\", \"x\": [1, {\"y\": true}]}\n"
      "}\n";
  EXPECT_EQ(where(text, {}), "1:1-4:2");
  EXPECT_EQ(where(text, {"domain"}), "2:13-2:16");
  EXPECT_EQ(where(text, {"domain"}, JsonPart::Key), "2:3-2:11");
  EXPECT_EQ(where(text, {"topics", "Base.cmd_vel"}, JsonPart::Key), "3:14-3:28");
  EXPECT_EQ(where(text, {"topics", "Base.cmd_vel"}), "3:30-3:40");
  EXPECT_EQ(where(text, {"topics", "x", "1", "y"}), "3:57-3:61");
  EXPECT_EQ(where(text, {"topics", "x", "0"}), "3:48-3:49");
  EXPECT_EQ(where(text, {"topics", "x", "0"}, JsonPart::Key), "none");  // an element has none
  EXPECT_EQ(where(text, {"topics", "x", "2"}), "none");
  EXPECT_EQ(where(text, {"qos"}), "none");
  EXPECT_EQ(where(text, {"domain", "a"}), "none");  // a number has no members
}

// Keys are compared as the library decodes them; the library keeps a repeated key's last value.
TEST(JsonPlaceTest, DecodesKeysAndTakesTheLastOfARepeatedOne) {
  EXPECT_EQ(where(R"({"a\u002eb": 1})", {"a.b"}), "1:14-1:15");
  EXPECT_EQ(where(R"({"\ud83d\ude00": 1, "\"": 2})", {"\xF0\x9F\x98\x80"}), "1:18-1:19");
  EXPECT_EQ(where(R"({"\ud83d\ude00": 1, "\"": 2})", {"\""}), "1:27-1:28");
  EXPECT_EQ(where(R"({"a": 1, "b": "}", "a": 2})", {"a"}), "1:25-1:26");
  EXPECT_EQ(where("\xEF\xBB\xBF{\"a\": 1}", {"a"}), "1:8-1:9");  // the BOM is a column
}

// "key first-line:column second-line:column" of the first repeated key, or "none".
std::string repeated(std::string_view text) {
  std::optional<JsonRepeatedKey> r = json_repeated_key(text);
  if (!r) return "none";
  return r->key + " " + std::to_string(r->first.begin.line) + ":" +
         std::to_string(r->first.begin.column) + " " + std::to_string(r->second.begin.line) + ":" +
         std::to_string(r->second.begin.column);
}

// A key repeated in one object is found at both places; the same key in two objects, a value
// that reads like a key, or a key in an array's objects are not repeats.
TEST(JsonRepeatedKeyTest, FindsAKeyRepeatedInOneObjectOnly) {
  EXPECT_EQ(repeated("{\n  \"a\": 1,\n  \"b\": 2,\n  \"a\": 3\n}"), "a 2:3 4:3");
  EXPECT_EQ(repeated(R"({"a": {"a": 1}, "b": {"a": 2}})"), "none");
  EXPECT_EQ(repeated(R"({"a": "b", "b": "a"})"), "none");
  EXPECT_EQ(repeated(R"([{"a": 1}, {"a": 2}, ["a", "a"]])"), "none");
  EXPECT_EQ(repeated(R"({"a": [1, {"x": 1}], "b": {"y": {}, "y": []}})"), "y 1:28 1:37");
  EXPECT_EQ(repeated(R"({"x": {"a": 1}, "x": 2})"), "x 1:2 1:17");  // the outer object's
  EXPECT_EQ(repeated(R"({"a\"b": 1, "c,{": 2, "a\u0022b": 3})"), "a\"b 1:2 1:23");  // decoded
  EXPECT_EQ(repeated("\"a\""), "none");
  EXPECT_EQ(repeated("{}"), "none");
}

// The scan walks nesting on the heap: the library's own depth does not exhaust the stack.
TEST(JsonRepeatedKeyTest, DeepNestingIsNoProblem) {
  std::string deep = std::string(100000, '[') + "{\"a\": 1, \"a\": 2}" + std::string(100000, ']');
  EXPECT_EQ(repeated(deep), "a 1:100002 1:100010");
}

// Columns count characters: a caret under the line lands on the value.
TEST(JsonPlaceTest, ColumnsCountCharactersNotBytes) {
  EXPECT_EQ(where("{\"\xC3\xA9t\xC3\xA9\": 1, \"b\": 2}", {"b"}), "1:17-1:18");
}

// Deep nesting is walked with a counter: no recursion to run out of stack.
TEST(JsonPlaceTest, DeepNestingIsNoProblem) {
  std::string deep =
      "{\"a\": " + std::string(200000, '[') + std::string(200000, ']') + ", \"b\": 1}";
  EXPECT_EQ(where(deep, {"b"}), "1:400014-1:400015");
}

TEST(JsonPlaceTest, MalformedTextPlacesNothing) {
  EXPECT_EQ(where("", {}), "none");
  EXPECT_EQ(where("{\"a\" 1}", {"a"}), "none");
  EXPECT_EQ(where("{\"a\": \"open", {"a"}), "none");
  EXPECT_EQ(where("[1, 2", {"5"}), "none");
  EXPECT_EQ(where("[1, 2]", {"-1"}), "none");
}

TEST(JsonPlaceTest, FindsANumberBeyondADouble) {
  EXPECT_EQ(json_number_overflow(R"({"e1e999": 1, "x": [2, -1e999]})"), 23u);
  EXPECT_EQ(json_number_overflow(R"([1e-999, 1.5e308])"), std::nullopt);
}

}  // namespace
}  // namespace arbc
