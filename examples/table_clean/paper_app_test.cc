// The simulated world on the embedded runtime with the paper's hand-written monitors: every
// scenario, over 20 seeds, ends with a clean table and no conflict; a wrong rule shows up as
// conflicts. (tests/table_clean/ runs the same with the monitors arbc generates.)
#include "examples/table_clean/paper_app.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "examples/table_clean/modules/world_environment.h"
#include "runtime/runtime.h"

namespace arbc::table_clean {
namespace {

struct Outcome {
  bool success = false;
  std::string summary;
  double end = 0;
  std::string log;
  // What the actors did.
  int slips = 0, cancels = 0, pulled = 0, moved_by_person = 0, face_targets = 0, objects = 0;
};

Outcome run(const model::App& app, const std::string& scenario, uint64_t seed) {
  RunOptions options;
  options.scenario = scenario;
  options.seed = seed;
  options.duration = 600;
  std::string error;
  auto runtime = Runtime::create(app, paper_monitors_dir(), options, &error);
  EXPECT_TRUE(runtime) << error;
  if (!runtime) return {};
  Outcome out;
  // Module logs (Speak's words) come here too; script errors would fail the run's checks.
  runtime->set_reporter([&out](const std::string& line) { out.log += line + "\n"; });
  runtime->run();
  out.success = runtime->environment()->success();
  out.summary = runtime->environment()->summary();
  out.end = seconds_of(runtime->now());
  World* world = dynamic_cast<WorldEnvironment&>(*runtime->environment()).world();
  out.slips = world->arm().slips();
  out.cancels = world->rake().cancels_honoured();
  out.pulled = world->rake().objects_pulled();
  out.moved_by_person = world->person().objects_moved();
  out.face_targets = world->referee().face_targets();
  out.objects = world->objects_total();
  return out;
}

class EveryScenario : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScenario, EndsCleanWithoutConflictOverTwentySeeds) {
  const model::App app = paper_app();
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const Outcome out = run(app, GetParam(), seed);
    EXPECT_TRUE(out.success) << out.summary << out.log;
    EXPECT_EQ(out.log.find("error"), std::string::npos) << out.log;
  }
}

TEST(PaperApp, EachScenarioExercisesItsPartOfTheWorld) {
  const model::App app = paper_app();
  const Outcome mixed = run(app, "mixed", 5);
  EXPECT_EQ(mixed.objects, 10);
  EXPECT_EQ(mixed.pulled, 3) << mixed.summary;
  EXPECT_EQ(mixed.moved_by_person, 3) << mixed.summary;
  EXPECT_GT(mixed.face_targets, 0) << mixed.summary;
  EXPECT_EQ(mixed.slips, 0);
  EXPECT_LT(mixed.end, 600) << "stopped early, when the table was clean";
  const Outcome perturbed = run(app, "perturbed", 5);
  EXPECT_EQ(perturbed.slips, 1) << perturbed.summary;
  EXPECT_GE(perturbed.cancels, 1) << perturbed.summary;
  EXPECT_TRUE(perturbed.success) << perturbed.summary;
  std::printf("%s%s", mixed.summary.c_str(), perturbed.summary.c_str());
}

INSTANTIATE_TEST_SUITE_P(PaperApp, EveryScenario,
                         ::testing::Values("reachable", "tool", "human", "mixed", "perturbed"));

TEST(PaperApp, TakingWhileHoldingShowsAsConflicts) {
  model::App app = paper_app();
  ASSERT_TRUE(set_constraint(app, "take", "e_arm_idle and e_pull_idle"));
  const Outcome out = run(app, "mixed", 1);
  EXPECT_FALSE(out.success);
  EXPECT_NE(out.summary.find("take_while_holding"), std::string::npos) << out.summary;
}

TEST(PaperApp, TakingWhileTheRakeIsOutShowsAsConflicts) {
  model::App app = paper_app();
  ASSERT_TRUE(set_constraint(app, "take", "not e_taken and e_arm_idle"));
  const Outcome out = run(app, "tool", 1);
  EXPECT_FALSE(out.success);
  EXPECT_NE(out.summary.find("take_while_rake_out"), std::string::npos) << out.summary;
}

TEST(PaperApp, SearchingWithoutThePriorityShowsAsConflicts) {
  model::App app = paper_app();
  ASSERT_TRUE(set_constraint(app, "search", "e_unreachable and e_arm_idle and e_pull_idle"));
  const Outcome out = run(app, "human", 1);
  EXPECT_FALSE(out.success);
  EXPECT_NE(out.summary.find("search_during_face_hold"), std::string::npos) << out.summary;
}

}  // namespace
}  // namespace arbc::table_clean
