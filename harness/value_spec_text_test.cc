// harness/value_spec_text.h: values in the spec's own syntax, record fields in the type's order.
#include "harness/value_spec_text.h"

#include <gtest/gtest.h>

namespace arbc::harness {
namespace {

TEST(ValueSpecTextTest, ValuesReadAsTheSpecWritesThem) {
  TypePtr cmd = parse_type("{verb: string, pos: vec3}");
  Value v = Value::record({{"pos", Value::vec3(0.3, 0.1, 0)}, {"verb", Value("take")}});
  EXPECT_EQ(value_spec_text(v, cmd.get()), "{ verb: \"take\", pos: vec3(0.3, 0.1, 0.0) }");
  EXPECT_EQ(value_spec_text(Value(int64_t{3}), nullptr), "3");
  EXPECT_EQ(value_spec_text(Value(2.0), nullptr), "2.0");
  EXPECT_EQ(value_spec_text(Value::list({Value(true), Value(false)}), nullptr), "[true, false]");
  EXPECT_EQ(value_spec_text(Value(), nullptr), "(no value)");
}

}  // namespace
}  // namespace arbc::harness
