// harness/test_replayer.h: the runtime behind the verifier's replays. A counterexample is
// reported only if this says the run really breaks the claim, so both answers are tested.
#include "harness/test_replayer.h"

#include "harness/harness_test_util.h"

namespace arbc::harness {
namespace {

// Two rules of two sources into D.d, both selected while e is present: not exclusive.
constexpr const char* kOverlap =
    "app overlap;\n"
    "module A { out a: float; }\n"
    "module B { out b: float; }\n"
    "module D { in d: float; }\n"
    "event e;\n"
    "arbitrate D.d {\n"
    "  left: from A.a when e;\n"
    "  right: from B.b when e;\n"
    "}\n";

// The app's one test, `expect exclusive D.d;` after `steps`.
model::TestCase exclusivity_test(const std::shared_ptr<const lower::LoweredApp>& app) {
  EXPECT_EQ(app->tests.size(), 1u);
  return app->tests.at(0);
}

std::shared_ptr<const lower::LoweredApp> with_test(const std::string& steps) {
  return testing::compiled(std::string(kOverlap) + "test \"t\" {\n" + steps +
                           "  expect exclusive D.d;\n}\n");
}

TEST(RuntimeTestReplayerTest, ARunThatBreaksTheClaimIsJudgedFailedInWords) {
  auto app = with_test("  at 0s set e;\n  at 100ms B.b <- 2.0;\n");
  ASSERT_TRUE(app);
  RuntimeTestReplayer replayer(app);
  std::string err;
  std::optional<std::string> failure = replayer.judge(exclusivity_test(app), &err);
  ASSERT_TRUE(failure) << err;
  EXPECT_NE(failure->find("'right' delivered at 100ms in a state where 'left' is selected too"),
            std::string::npos)
      << *failure;
}

TEST(RuntimeTestReplayerTest, ARunThatKeepsTheClaimIsJudgedPassed) {
  auto app = with_test("  at 100ms B.b <- 2.0;\n");  // e absent: nothing is selected
  ASSERT_TRUE(app);
  RuntimeTestReplayer replayer(app);
  std::string err;
  std::optional<std::string> failure = replayer.judge(exclusivity_test(app), &err);
  ASSERT_TRUE(failure) << err;
  EXPECT_EQ(*failure, "");
}

TEST(RuntimeTestReplayerTest, AReplayGivesWhatHappenedAtThePortInOrder) {
  auto app = with_test("  at 0s set e;\n  at 100ms A.a <- 1.0;\n");
  ASSERT_TRUE(app);
  RuntimeTestReplayer replayer(app);
  std::string err;
  auto records = replayer.replay(exclusivity_test(app), "D.d", &err);
  ASSERT_TRUE(records) << err;
  std::vector<std::string> seen;
  for (const verify::ReplayRecord& r : *records)
    if (r.kind == verify::ReplayRecord::Kind::Deliver) seen.push_back(r.connection);
  EXPECT_EQ(seen, std::vector<std::string>{"left"});
}

}  // namespace
}  // namespace arbc::harness
