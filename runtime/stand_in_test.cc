// Stand-ins (runtime/stand_in.h): a stub source publishes at its rate, a sink counts what
// reaches it, and only a log that asks for every message keeps them (issue 40: a long
// `arbc run --stub` grew without bound because the sink kept every value).
#include "runtime/stand_in.h"

#include <gtest/gtest.h>

#include "runtime/runtime_test_util.h"

namespace arbc {
namespace {

using testing::TestApp;

struct StandInRun {
  uint64_t published = 0;
  ReceivedTally tally;
  size_t kept = 0;
  std::string summary;
};

StandInRun run_stubs(bool keep_received) {
  TestApp t;
  t.module("Camera", {"out x: float"});
  t.module("Screen", {"in x: float"});
  t.connect("show", "Camera.x", "Screen.x", "true");
  auto log = std::make_shared<StandInLog>();
  log->stub.enabled = true;
  log->stub.period_of_port["Camera.x"] = 0.01;  // 100 Hz
  log->keep_received = keep_received;
  std::vector<std::string> stand_ins;
  Registry registry = registry_with_stand_ins(t.app, Registry(), log, &stand_ins);
  RunOptions options;
  options.duration = 10;
  std::string error;
  auto rt = Runtime::create(t.app, t.dir, options, &error, registry);
  EXPECT_TRUE(rt) << error;
  if (!rt) return {};
  rt->run();
  return {log->published["Camera.x"], log->tally["Screen.x"], log->received.size(),
          stand_in_summary(t.app, stand_ins, *log)};
}

TEST(StandInTest, ASinkCountsWhatReachesItAndKeepsValuesOnlyWhenAsked) {
  StandInRun all = run_stubs(true);
  StandInRun counted = run_stubs(false);
  EXPECT_GE(all.published, 1000u);  // 100 Hz for 10 s
  EXPECT_EQ(all.tally.count, all.published);
  EXPECT_EQ(all.kept, all.published);
  EXPECT_EQ(counted.kept, 0u);  // a run's sink keeps nothing per message
  EXPECT_EQ(counted.tally.count, all.tally.count);
  EXPECT_EQ(counted.tally.first, Nanos(0));
  EXPECT_EQ(counted.tally.last.connection, "show");
  EXPECT_NE(counted.summary.find("Screen.x (stand-in sink): received " +
                                 std::to_string(all.published) + ", first at 0s, last at "),
            std::string::npos)
      << counted.summary;
  EXPECT_EQ(counted.summary, all.summary);  // the same words either way
}

}  // namespace
}  // namespace arbc
