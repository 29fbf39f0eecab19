// Stand-ins (runtime/stand_in.h): a stub source publishes at its rate, a sink counts what
// reaches it, and only a log that asks for every message keeps them (issue 40: a long
// `arbc run --stub` grew without bound because the sink kept every value).
#include "runtime/stand_in.h"

#include <gtest/gtest.h>

#include "runtime/runtime_test_util.h"
#include "runtime/stand_in_sample.h"

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

// --stub samples reach both sides of a threshold the spec compares a part with, the threshold
// itself, and the strings it compares a part with (issue 39: floats stayed in [0, 1), so a
// 45 dB threshold was never reached); parts nothing compares keep the plain ranges.
TEST(StandInTest, SamplesReachBothSidesOfEveryThresholdTheSpecTests) {
  SamplePlan plan;
  plan.compared["db"].numbers = {45.0};
  plan.compared["count"].numbers = {-3.0, 100.0};
  plan.compared["source"].strings = {"voice"};
  plan.compared["len(items)"].numbers = {5.0};
  TypePtr t = parse_type("{db: float, count: int, source: string, other: float, items: list<int>}");
  std::mt19937_64 rng(7);
  int loud = 0, quiet = 0, at_45 = 0, voice = 0, over_100 = 0, under_minus_3 = 0, long_lists = 0;
  for (int i = 0; i < 400; ++i) {
    Value v = sample_value(*t, rng, plan);
    double db = v["db"].as_float();
    (db > 45 ? loud : quiet)++;
    at_45 += db == 45.0;
    voice += v["source"].as_string() == "voice";
    int64_t count = v["count"].as_int();
    over_100 += count > 100;
    under_minus_3 += count < -3;
    double other = v["other"].as_float();
    EXPECT_TRUE(other >= 0 && other < 1) << other;
    long_lists += v["items"].size() >= 5;
    EXPECT_LE(v["items"].size(), static_cast<size_t>(kMaxSampleListLength));
  }
  EXPECT_GT(loud, 40);
  EXPECT_GT(quiet, 40);
  EXPECT_GT(at_45, 10);
  EXPECT_GT(voice, 40);
  EXPECT_LT(voice, 360);  // and strings no condition names
  EXPECT_GT(over_100, 10);
  EXPECT_GT(under_minus_3, 10);
  EXPECT_GT(long_lists, 40);
}

}  // namespace
}  // namespace arbc
