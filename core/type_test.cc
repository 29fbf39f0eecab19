#include "core/type.h"

#include <gtest/gtest.h>

#include <limits>

namespace arbc {
namespace {

TEST(TypeTest, ParsesAndPrintsCanonicalText) {
  std::string error;
  TypePtr t = parse_type(" list< { pos : vec3, dist:float } > ", &error);
  ASSERT_TRUE(t) << error;
  EXPECT_EQ(t->to_string(), "list<{pos: vec3, dist: float}>");
}

TEST(TypeTest, RecordsCompareByFieldNameInAnyOrder) {
  TypePtr a = parse_type("{verb: string, pos: vec3}");
  TypePtr b = parse_type("{pos: vec3, verb: string}");
  TypePtr c = parse_type("{pos: vec3, verb: int}");
  EXPECT_TRUE(same_type(*a, *b));
  EXPECT_FALSE(same_type(*a, *c));
  EXPECT_FALSE(same_type(*parse_type("int"), *parse_type("float")));
}

// Every spelling of core/number_types.def reads back as a type whose canonical text reads back
// as the same type; `int`, `int64` are one type, `byte`, `char`, `uint8` another.
TEST(TypeTest, NumberTypesByEverySpelling) {
  for (const std::string& name : Type::number_names()) {
    TypePtr t = parse_type(name);
    ASSERT_TRUE(t) << name;
    TypePtr again = parse_type(t->to_string());
    ASSERT_TRUE(again) << t->to_string();
    EXPECT_TRUE(same_type(*t, *again)) << name;
  }
  EXPECT_EQ(parse_type("int64")->to_string(), "int");
  EXPECT_EQ(parse_type("float64")->to_string(), "float");
  EXPECT_EQ(parse_type("byte")->to_string(), "uint8");
  EXPECT_EQ(parse_type("{sec: int32, nanosec: uint32}")->to_string(),
            "{sec: int32, nanosec: uint32}");
  EXPECT_FALSE(same_type(*parse_type("int32"), *parse_type("uint32")));
  EXPECT_FALSE(same_type(*parse_type("int32"), *parse_type("int")));
  EXPECT_FALSE(same_type(*parse_type("float32"), *parse_type("float")));
  EXPECT_TRUE(same_type(*parse_type("char"), *parse_type("uint8")));
}

TEST(TypeTest, RangesOfTheIntegerWidths) {
  EXPECT_EQ(parse_type("int8")->range_text(), "-128 to 127");
  EXPECT_EQ(parse_type("uint16")->range_text(), "0 to 65535");
  EXPECT_EQ(parse_type("int32")->range_text(), "-2147483648 to 2147483647");
  EXPECT_EQ(parse_type("uint32")->range_text(), "0 to 4294967295");
  EXPECT_EQ(parse_type("uint64")->range_text(), "0 to 18446744073709551615");
  TypePtr i8 = parse_type("int8");
  EXPECT_TRUE(i8->holds(int64_t{-128}));
  EXPECT_FALSE(i8->holds(int64_t{128}));
  EXPECT_FALSE(parse_type("uint8")->holds(int64_t{-1}));
  EXPECT_TRUE(parse_type("int")->holds(INT64_MIN));
}

// float32 holds a double exactly or not at all; NaN and the infinities are values of it.
TEST(TypeTest, Float32HoldsWhatRoundsToItself) {
  TypePtr f = parse_type("float32");
  EXPECT_TRUE(f->holds(0.5));
  EXPECT_TRUE(f->holds(-0.0));
  EXPECT_FALSE(f->holds(0.1));
  EXPECT_TRUE(f->holds(static_cast<double>(0.1f)));
  EXPECT_TRUE(f->holds(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_TRUE(f->holds(-std::numeric_limits<double>::infinity()));
  EXPECT_TRUE(f->holds(static_cast<double>(std::numeric_limits<float>::max())));
  EXPECT_FALSE(f->holds(1e39));  // beyond float32: it would be inf
  EXPECT_TRUE(parse_type("float")->holds(0.1));
}

TEST(TypeTest, ArithmeticPromotesTheSizedTypes) {
  EXPECT_EQ(promoted(parse_type("int8"))->to_string(), "int");
  EXPECT_EQ(promoted(parse_type("uint32"))->to_string(), "int");
  EXPECT_EQ(promoted(parse_type("float32"))->to_string(), "float");
  EXPECT_EQ(promoted(parse_type("uint64"))->to_string(), "uint64");
  EXPECT_EQ(arithmetic_type(*parse_type("uint64"), *parse_type("uint8"))->to_string(), "uint64");
  EXPECT_EQ(arithmetic_type(*parse_type("int16"), *parse_type("int8"))->to_string(), "int");
  EXPECT_EQ(arithmetic_type(*parse_type("float32"), *parse_type("int8"))->to_string(), "float");
}

// Sizes are part of the type and of its text: T[N], list<T, N>, string<N>, nested anywhere.
TEST(TypeTest, SizedListsAndStringsRoundTrip) {
  for (const char* text : {"float[9]", "list<int, 8>", "string<16>", "{a: uint8}[2]",
                           "list<string<4>, 3>[2]", "{cov: float32[36], names: list<string>}"}) {
    std::string error;
    TypePtr t = parse_type(text, &error);
    ASSERT_TRUE(t) << text << ": " << error;
    EXPECT_EQ(t->to_string(), text);
    EXPECT_TRUE(same_type(*t, *parse_type(t->to_string())));
  }
  TypePtr fixed = parse_type("float[9]");
  EXPECT_TRUE(fixed->fixed);
  EXPECT_EQ(fixed->size, 9);
  EXPECT_FALSE(same_type(*fixed, *parse_type("list<float>")));
  EXPECT_FALSE(same_type(*fixed, *parse_type("list<float, 9>")));
  EXPECT_FALSE(same_type(*fixed, *parse_type("float[8]")));
  EXPECT_FALSE(same_type(*parse_type("string<3>"), *parse_type("string")));
  std::string error;
  for (const char* bad :
       {"float[0]", "list<int, 0>", "string<4097>", "int[99999999999]", "string<>", "int[3"}) {
    EXPECT_FALSE(parse_type(bad, &error)) << bad;
  }
  EXPECT_TRUE(parse_type("int[4096]"));
}

TEST(TypeTest, RejectsMalformedText) {
  std::string error;
  EXPECT_FALSE(parse_type("list<", &error));
  EXPECT_FALSE(parse_type("quaternion", &error));
  EXPECT_EQ(error, "unknown type 'quaternion'");
  EXPECT_FALSE(parse_type(
      [] {
        std::string deep;
        for (int i = 0; i < 1000; ++i) deep += "list<";
        return deep;
      }(),
      &error));
  EXPECT_EQ(error, "type nested too deeply");
}

}  // namespace
}  // namespace arbc
