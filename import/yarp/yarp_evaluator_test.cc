#include "import/yarp/yarp_evaluator.h"

#include <gtest/gtest.h>

namespace arbc::yarp {
namespace {

using R = YarpVerdict::Result;

TEST(YarpEvaluator, SubstitutesNamesAsSubstrings) {
  EXPECT_EQ(yarp_lookups("e and not (e_ball)"), (std::vector<std::string>{"e", "e_ball"}));
  EXPECT_EQ(yarp_substitute("e and not e_ball", {"e", "e_ball"}), "true and not trutrue");
  EXPECT_EQ(yarp_substitute("e1 or e10", {"e10"}), "false or false0");
  EXPECT_EQ(yarp_substitute("  a and b ", {"a", "b"}), "true truend true");
}

TEST(YarpEvaluator, ReproducesYarpsWrongAnswers) {
  auto ev = YarpEvaluator::create();
  ASSERT_TRUE(ev);
  EXPECT_EQ(ev->evaluate("e and not e_ball", {"e", "e_ball"}).result, R::True);
  EXPECT_EQ(ev->evaluate("e1 or e10", {"e10"}).result, R::NotBoolean);
  EXPECT_EQ(ev->evaluate("a and b", {"a", "b"}).result, R::LuaError);
  EXPECT_EQ(ev->evaluate("e_ball && e_line", {"e_ball"}).result, R::LuaError);
  EXPECT_EQ(ev->evaluate("", {}).result, R::True);
  EXPECT_EQ(ev->evaluate("e_ball and not e_line", {"e_ball"}).result, R::True);
  EXPECT_EQ(ev->evaluate("e_ball and not e_line", {"e_ball", "e_line"}).result, R::False);
}

TEST(YarpEvaluator, MeaningFindsTheSmallestWitness) {
  auto ev = YarpEvaluator::create();
  ConstraintMeaning m = constraint_meaning(*ev, "e and not e_ball");
  ASSERT_TRUE(m.parsed);
  ASSERT_TRUE(m.simulated);
  ASSERT_TRUE(m.differs);
  EXPECT_EQ(m.witness, (std::vector<std::string>{"e", "e_ball"}));
  EXPECT_TRUE(m.witness_verdict.accepts());
  EXPECT_FALSE(m.written_at_witness);
  // YARP: "e" selects whenever e is present, whatever e_ball.
  EXPECT_TRUE(evaluate(m.yarp, {"e", "e_ball"}));
  EXPECT_TRUE(evaluate(m.yarp, {"e"}));
  EXPECT_FALSE(evaluate(m.yarp, {"e_ball"}));

  ConstraintMeaning ok = constraint_meaning(*ev, "e_ball and not e_line");
  EXPECT_FALSE(ok.differs);
  EXPECT_EQ(ok.yarp, ok.written);

  ConstraintMeaning bad = constraint_meaning(*ev, "e_ball && e_line");
  EXPECT_FALSE(bad.parsed);
  EXPECT_TRUE(bad.differs);
  EXPECT_EQ(bad.yarp, Constraint::constant(false));
}

}  // namespace
}  // namespace arbc::yarp
