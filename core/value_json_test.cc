#include "core/value_json.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace arbc
