// harness/test_runner.h: a spec's tests run on the runtime in simulated time, and a failed
// expectation says what happened instead.
#include "harness/test_runner.h"

#include "harness/harness_test_util.h"

namespace arbc::harness {
namespace {

std::vector<TestOutcome> run_tests(const std::string& tests) {
  auto lowered = testing::compiled(std::string(testing::kGaze) + tests);
  if (!lowered) return {};
  TestApp ready = write_test_app(*lowered, testing::scratch());
  EXPECT_TRUE(ready.ok) << ready.error;
  std::vector<TestOutcome> out;
  for (const model::TestCase& t : lowered->tests)
    out.push_back(run_test_case(ready.app, ready.dir, t));
  return out;
}

TEST(TestRunnerTest, ATestPassesWhenTheAppDoesWhatItExpects) {
  std::vector<TestOutcome> out = run_tests(
      "test \"search\" {\n"
      "  at 100ms LookAround.gaze <- vec3(1.0, 0.0, 0.0);\n"
      "  expect HeadControl.gaze receives vec3(1.0, 0.0, 0.0) at 100ms;\n"
      "}\n");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].passed) << out[0].detail;
  EXPECT_EQ(out[0].name, "search");
  EXPECT_EQ(out[0].detail, "");
}

TEST(TestRunnerTest, AFailedExpectationSaysWhatHappenedInstead) {
  std::vector<TestOutcome> out = run_tests(
      "test \"a face holds the gaze\" {\n"
      "  at 0s FaceDetector.face <- { pos: vec3(0.0, 0.5, 1.0), certainty: 0.9 };\n"
      "  at 100ms FaceDetector.face <- { pos: vec3(0.0, 0.5, 1.0), certainty: 0.9 };\n"
      "  at 500ms LookAround.gaze <- vec3(1.0, 0.0, 0.0);\n"
      "  expect HeadControl.gaze receives vec3(1.0, 0.0, 0.0) at 500ms;\n"
      "}\n");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_FALSE(out[0].passed);
  EXPECT_NE(out[0].detail.find("expected HeadControl.gaze receives vec3(1.0, 0.0, 0.0) at 500ms"),
            std::string::npos)
      << out[0].detail;
  EXPECT_NE(out[0].detail.find("not-selected"), std::string::npos) << out[0].detail;
}

TEST(TestRunnerTest, ATestOfOneRuleRunsThatRuleAlone) {
  std::vector<TestOutcome> out = run_tests(
      "test \"track alone\" on track {\n"
      "  at 0s set e_face;\n"
      "  at 10ms FaceDetector.face <- { pos: vec3(0.0, 0.5, 1.0), certainty: 0.9 };\n"
      "  expect HeadControl.gaze receives vec3(0.0, 0.5, 1.0) at 10ms;\n"
      "}\n");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].passed) << out[0].detail;
}

}  // namespace
}  // namespace arbc::harness
