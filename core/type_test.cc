#include "core/type.h"

#include <gtest/gtest.h>

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
