#include "core/value_json.h"

#include <gtest/gtest.h>

#include <limits>

namespace arbc {
namespace {

Value read(const char* json, const char* type, std::string* err) {
  std::optional<Value> v = value_from_json(nlohmann::json::parse(json), *parse_type(type), err);
  return v ? *v : Value();
}

TEST(ValueJsonTest, RoundTripsWhatTracesPrint) {
  Value obj = Value::record({{"pos", Value::vec3(0.3, 0.1, 0)}, {"dist", 0.25}});
  Value list = Value::list({obj, obj});
  std::string err;
  Value back = read(list.to_json().c_str(), "list<{pos: vec3, dist: float}>", &err);
  EXPECT_EQ(err, "");
  EXPECT_EQ(back, list);
  EXPECT_EQ(read("[1, 2, 3]", "vec3", &err), Value::vec3(1, 2, 3));
  EXPECT_TRUE(read("2", "float", &err).is_float());  // an int literal is a float where one is due
  EXPECT_TRUE(read("2.0", "int", &err).is_int());
}

TEST(ValueJsonTest, NamesTheFieldThatDoesNotFit) {
  std::string err;
  read(R"({"pos": {"x": 1, "y": "a", "z": 0}, "certainty": 0.9})", "{pos: vec3, certainty: float}",
       &err);
  EXPECT_EQ(err, "field pos.y: expected float, got string");
  read(R"({"pos": [0, 0, 0]})", "{pos: vec3, certainty: float}", &err);
  EXPECT_EQ(err, "missing field 'certainty' (float)");
  read(R"({"pos": [0, 0, 0], "certainty": 1, "extra": 1})", "{pos: vec3, certainty: float}", &err);
  EXPECT_EQ(err, "unknown field 'extra' (the type is {pos: vec3, certainty: float})");
  read(R"(["a", 3])", "list<string>", &err);
  EXPECT_EQ(err, "item 1: expected string, got int");
  read("2.5", "int", &err);
  EXPECT_EQ(err, "expected int, got float");
}

// 2^63 was read as -2^63 (issue 40): an int outside 64 bits is refused, whatever its spelling.
TEST(ValueJsonTest, AnIntBeyond64BitsIsRefusedNotWrapped) {
  std::string err;
  EXPECT_EQ(read("9223372036854775807", "int", &err), Value(int64_t{9223372036854775807}));
  EXPECT_EQ(read("-9223372036854775808", "int", &err), Value(std::numeric_limits<int64_t>::min()));
  EXPECT_EQ(err, "");
  for (const char* beyond : {"9223372036854775808", "18446744073709551615"}) {
    err.clear();
    EXPECT_FALSE(value_from_json(nlohmann::json::parse(beyond), *parse_type("int"), &err));
    EXPECT_NE(err.find("is beyond the range of int, a 64-bit integer"), std::string::npos)
        << beyond << ": " << err;
  }
  // Read as doubles by the JSON parser, so no longer exact: -9223372036854775809 is -2^63.
  for (const char* inexact : {"99999999999999999999999", "-9223372036854775809", "1e19", "1e18"}) {
    err.clear();
    EXPECT_FALSE(value_from_json(nlohmann::json::parse(inexact), *parse_type("int"), &err));
    EXPECT_NE(err.find("is not an exact int"), std::string::npos) << inexact << ": " << err;
  }
  EXPECT_EQ(read("1e15", "int", &err), Value(int64_t{1000000000000000}));
  err.clear();
  read(R"({"n": 9223372036854775808})", "{n: int}", &err);
  EXPECT_EQ(err.rfind("field n: 9223372036854775808 is beyond", 0), 0u) << err;
}

}  // namespace
}  // namespace arbc
