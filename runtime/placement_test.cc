// Where modules run (RunOptions::host, ::mediate) and the in-process transport's refusal of a
// partial placement; the scaled wall clock of distributed runs.
#include <gtest/gtest.h>

#include <chrono>

#include "runtime/runtime_test_util.h"

namespace arbc {

using namespace std::chrono_literals;
namespace {

using testing::TestApp;

TEST(PlacementTest, InprocTransportRefusesAModuleThatRunsElsewhere) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("c", "Src.x", "Sink.x", "true");
  RunOptions o;
  o.host = ModuleSet::none();
  o.host.names.insert("Src");
  std::string error;
  EXPECT_FALSE(Runtime::create(t.app, t.dir, o, &error, t.registry));
  EXPECT_NE(error.find("module Sink is not run by this process"), std::string::npos) << error;
  EXPECT_NE(error.find("--transport dds"), std::string::npos) << error;
}

TEST(PlacementTest, InprocTransportRefusesAnInputMediatedElsewhere) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("c", "Src.x", "Sink.x", "true");
  RunOptions o;
  o.mediate = ModuleSet::none();
  std::string error;
  EXPECT_FALSE(Runtime::create(t.app, t.dir, o, &error, t.registry));
  EXPECT_NE(error.find("module Sink is not run by this process"), std::string::npos) << error;
}

TEST(PlacementTest, ModuleSetContainsWhatItNames) {
  ModuleSet s = ModuleSet::none();
  EXPECT_TRUE(s.empty());
  EXPECT_FALSE(s.contains("A"));
  s.names.insert("A");
  EXPECT_TRUE(s.contains("A"));
  EXPECT_FALSE(s.contains("B"));
  EXPECT_TRUE(ModuleSet::everything().contains("B"));
}

// Time runs `scale` times as fast as the wall clock: 2 s of run time at scale 20 take at
// least 0.1 s of wall time (never less: a task cannot run before its time) and, bounded
// generously for a loaded machine, far less than the 2 s an unscaled clock takes.
TEST(PlacementTest, ScaledRealtimeExecutorRunsFasterThanTheWallClock) {
  RealtimeExecutor ex(20);
  Nanos ran_at{-1};
  ex.post(1500ms, [&] { ran_at = ex.now(); });
  auto begin = std::chrono::steady_clock::now();
  ex.run(2s);
  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  EXPECT_GE(ran_at, 1500ms);
  EXPECT_GE(ex.now(), 2s);
  EXPECT_GE(wall, 0.1 - 1e-3);
  EXPECT_LT(wall, 1.5) << "2 s at scale 20 took " << wall << " s of wall time";
}

}  // namespace
}  // namespace arbc
