#include "verify/replay.h"

#include <gtest/gtest.h>

#include "verify/test_models.h"

namespace arbc::verify {
namespace {

using testing::parse;

TEST(Replay, RuntimeEvaluatorAgreesWithTheReference) {
  const char* formulas[] = {"a and not b", "a or (b and not c)", "not (a or b)", "true",
                            "false",       "a and not a"};
  std::vector<std::vector<std::string>> states = {{}, {"a"}, {"b"}, {"a", "b"}, {"a", "c"}};
  for (const char* f : formulas) {
    for (const auto& s : states) {
      std::set<std::string> present(s.begin(), s.end());
      EXPECT_EQ(runtime_holds(parse(f), s), evaluate(parse(f), present)) << f;
    }
  }
}

TEST(Replay, EventNamesThatArePrefixesDoNotInterfere) {
  // YARP's substring substitution gets this wrong; the runtime's evaluator must not.
  EXPECT_TRUE(runtime_holds(parse("e and not e_ball"), {"e"}));
  EXPECT_FALSE(runtime_holds(parse("e and not e_ball"), {"e_ball"}));
}

TEST(Replay, DescribeStateListsTheEventsTheConstraintReads) {
  EXPECT_EQ(describe_state(parse("not e_taken and e_arm_idle"), {"e_arm_idle", "e_other"}),
            "e_arm_idle present, e_taken absent");
  EXPECT_EQ(describe_state(parse("true"), {}), "no events");
}

}  // namespace
}  // namespace arbc::verify
