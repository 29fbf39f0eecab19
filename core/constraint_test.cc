#include "core/constraint.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

Constraint parse_ok(std::string_view text) {
  ConstraintParse p = parse_constraint(text);
  EXPECT_TRUE(p.ok) << text << ": " << p.error;
  return p.constraint;
}

TEST(ConstraintTest, PrintsWithFewestParentheses) {
  EXPECT_EQ(parse_ok("not e_taken and e_arm_idle and e_pull_idle").to_string(),
            "not e_taken and e_arm_idle and e_pull_idle");
  EXPECT_EQ(parse_ok("(a or b) and not (c and d)").to_string(), "(a or b) and not (c and d)");
  EXPECT_EQ(parse_ok("a or (b and c)").to_string(), "a or b and c");
  EXPECT_EQ(parse_ok("((a))").to_string(), "a");
}

TEST(ConstraintTest, TextRoundTrips) {
  for (const char* text :
       {"true", "false", "not not a", "a and (b or c or not d)", "e or e_ball"}) {
    Constraint c = parse_ok(text);
    EXPECT_EQ(parse_ok(c.to_string()), c) << text;
  }
}

TEST(ConstraintTest, NamesAreWholeTokens) {
  Constraint c = parse_ok("e and not e_ball");
  EXPECT_TRUE(evaluate(c, {"e"}));
  EXPECT_FALSE(evaluate(c, {"e", "e_ball"}));
  EXPECT_FALSE(evaluate(c, {"e_ball"}));
  Constraint keywordish = parse_ok("nota and andy");
  EXPECT_TRUE(evaluate(keywordish, {"nota", "andy"}));
}

TEST(ConstraintTest, BuildersFoldConstants) {
  Constraint x = Constraint::event_ref("x");
  EXPECT_EQ(Constraint::conjunction({Constraint::constant(true), x}).to_string(), "x");
  EXPECT_EQ(Constraint::conjunction({x, Constraint::constant(false)}).to_string(), "false");
  EXPECT_EQ(Constraint::disjunction({Constraint::constant(false), x}).to_string(), "x");
  EXPECT_EQ(Constraint::disjunction({x, Constraint::constant(true)}).to_string(), "true");
  EXPECT_EQ(Constraint::conjunction({}).to_string(), "true");
  EXPECT_EQ(Constraint::conjunction({x, Constraint::event_ref("y"), x}).to_string(), "x and y");
  EXPECT_EQ(Constraint::conjunction({x, x}).to_string(), "x");
  // Nested chains flatten in order, whichever operand holds the chain; an `or` stays nested.
  Constraint y = Constraint::event_ref("y"), z = Constraint::event_ref("z");
  Constraint xy = Constraint::conjunction({x, Constraint::negate(y)});
  Constraint chain = Constraint::conjunction({xy, z, Constraint::conjunction({z, x, y})});
  ASSERT_EQ(chain.args.size(), 4u);
  EXPECT_EQ(chain.to_string(), "x and not y and z and y");
  EXPECT_EQ(Constraint::conjunction({z, Constraint::disjunction({x, y}), xy}).to_string(),
            "z and (x or y) and x and not y");
  EXPECT_EQ(
      Constraint::disjunction({Constraint::disjunction({x, y}), z, Constraint::constant(false)})
          .to_string(),
      "x or y or z");
  EXPECT_EQ(parse_constraint("true and x").constraint.to_string(), "true and x");
}

TEST(ConstraintTest, ReportsErrorsWithOffsets) {
  ConstraintParse p = parse_constraint("a and (b or");
  EXPECT_FALSE(p.ok);
  EXPECT_EQ(p.error, "expected an event name, 'not', 'true', 'false' or '('");
  EXPECT_EQ(p.offset, 11u);
  p = parse_constraint("a b");
  EXPECT_FALSE(p.ok);
  EXPECT_EQ(p.error, "unexpected 'b' after the end of the constraint");
  p = parse_constraint("a & b");
  EXPECT_FALSE(p.ok);
  EXPECT_EQ(p.offset, 2u);
}

// The project's one error form (docs/design.md#reporting-errors): the value, or *err.
TEST(ConstraintTest, TheErrFormGivesTheConstraintOrSaysWhereItFailed) {
  std::string err;
  std::optional<Constraint> c = parse_constraint("a and (b or", &err);
  EXPECT_FALSE(c);
  EXPECT_EQ(err, "expected an event name, 'not', 'true', 'false' or '(' at offset 11");
  err.clear();
  c = parse_constraint("not (a or b)", &err);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->to_string(), "not (a or b)");
  EXPECT_TRUE(err.empty());
}

TEST(ConstraintTest, DeepNestingIsAnErrorNotACrash) {
  std::string deep(100000, '(');
  ConstraintParse p = parse_constraint(deep + "a" + std::string(100000, ')'));
  EXPECT_FALSE(p.ok);
  EXPECT_EQ(p.error, "constraint nested too deeply");
  std::string nots;
  for (int i = 0; i < 100000; ++i) nots += "not ";
  EXPECT_FALSE(parse_constraint(nots + "a").ok);
}

}  // namespace
}  // namespace arbc
