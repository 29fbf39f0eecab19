#include "core/value.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

TEST(ValueTest, BuildsAndReadsNestedValues) {
  Value obj = Value::record({{"pos", Value::vec3(0.1, 0.2, 0.3)}, {"dist", 0.5}});
  Value list = Value::list({obj, obj});
  EXPECT_EQ(list.size(), 2u);
  EXPECT_DOUBLE_EQ(list[1]["dist"].as_float(), 0.5);
  EXPECT_DOUBLE_EQ(list[0]["pos"].as_vec3().y(), 0.2);
  EXPECT_TRUE(list[5].is_none());
  EXPECT_TRUE(obj["missing"].is_none());
  EXPECT_EQ(Value(3).as_float(), 3.0);
  EXPECT_EQ(Value("x").as_int(), 0);  // wrong kind: neutral value, no crash
}

TEST(ValueTest, CopiesAreIndependent) {
  Value a = Value::list({1, 2});
  Value b = a;
  b.push_back(3);
  EXPECT_EQ(a.size(), 2u);
  EXPECT_EQ(b.size(), 3u);
  Value r = Value::record({{"k", 1}});
  Value s = r;
  s.set("k", 2);
  EXPECT_EQ(r["k"].as_int(), 1);
  EXPECT_EQ(s["k"].as_int(), 2);
}

TEST(ValueTest, JsonIsDeterministicWithSortedFields) {
  Value v = Value::record({{"verb", "take"}, {"pos", Value::vec3(1, 0.5, -2)}, {"n", 3}});
  EXPECT_EQ(v.to_json(), R"({"n":3,"pos":{"x":1.0,"y":0.5,"z":-2.0},"verb":"take"})");
  EXPECT_EQ(Value(0.1).to_json(), "0.1");
  EXPECT_EQ(Value("a\"b\n").to_json(), R"("a\"b\n")");
}

TEST(ValueTest, ConformsChecksTypesAndSaysWhere) {
  TypePtr t = parse_type("list<{pos: vec3, dist: float}>");
  ASSERT_TRUE(t);
  Value good = Value::list({Value::record({{"pos", Value::vec3(0, 0, 0)}, {"dist", 1}})});
  EXPECT_TRUE(conforms(good, *t));
  Value bad = Value::list({Value::record({{"pos", "here"}, {"dist", 1.0}})});
  std::string why;
  EXPECT_FALSE(conforms(bad, *t, &why));
  EXPECT_EQ(why, "element 0: field pos: expected vec3, got string");
  EXPECT_FALSE(conforms(Value::record({{"dist", 1.0}}), *t->element, &why));
  EXPECT_EQ(why, "missing field pos");
}

// A value of a sized type is in its range; a uint64 is any bit pattern; a float32 rounds to
// itself. What does not conform is dropped by the runtime as bad-type, with this reason.
TEST(ValueTest, ConformsChecksTheRangeOfSizedTypes) {
  std::string why;
  EXPECT_TRUE(conforms(Value(int64_t{127}), *parse_type("int8")));
  EXPECT_FALSE(conforms(Value(int64_t{128}), *parse_type("int8"), &why));
  EXPECT_EQ(why, "128 is not int8 (-128 to 127)");
  EXPECT_FALSE(conforms(Value(int64_t{-1}), *parse_type("uint32"), &why));
  EXPECT_TRUE(conforms(Value(int64_t{-1}), *parse_type("uint64")));  // 2^64 - 1
  EXPECT_TRUE(conforms(Value(0.5), *parse_type("float32")));
  EXPECT_FALSE(conforms(Value(0.1), *parse_type("float32"), &why));
  EXPECT_EQ(why, "0.1 is not a float32 value (it would round)");
  EXPECT_FALSE(conforms(Value(int64_t{16777217}), *parse_type("float32"), &why));
}

// T[N] has exactly N elements, list<T, N> and string<N> at most N: the proof assumed it, so
// the runtime drops any other value as bad-type with this reason.
TEST(ValueTest, ConformsChecksSizes) {
  std::string why;
  Value three = Value::list({Value(1.0), Value(2.0), Value(3.0)});
  EXPECT_TRUE(conforms(three, *parse_type("float[3]")));
  EXPECT_FALSE(conforms(three, *parse_type("float[4]"), &why));
  EXPECT_EQ(why, "a list of 3 elements is not a float[4] (exactly 4)");
  EXPECT_TRUE(conforms(three, *parse_type("list<float, 3>")));
  EXPECT_FALSE(conforms(three, *parse_type("list<float, 2>"), &why));
  EXPECT_EQ(why, "a list of 3 elements is not a list<float, 2> (at most 2)");
  EXPECT_TRUE(conforms(Value("abc"), *parse_type("string<3>")));
  EXPECT_FALSE(conforms(Value("abcd"), *parse_type("string<3>"), &why));
  EXPECT_EQ(why, "a string of 4 bytes is not a string<3> (at most 3 bytes)");
  EXPECT_FALSE(conforms(Value::record({{"v", three}}), *parse_type("{v: float[2]}"), &why));
  EXPECT_EQ(why, "field v: a list of 3 elements is not a float[2] (exactly 2)");
}

}  // namespace
}  // namespace arbc
