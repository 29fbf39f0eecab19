#include "import/yarp/script_runner.h"

#include <gtest/gtest.h>

namespace arbc::yarp {
namespace {

const MonitorContext kContext{"ball.lua", "/ball/out", "/motor/in", "tcp"};

TEST(ScriptRunner, CapturesTheConstraintCreateSets) {
  ScriptRun run = run_script(R"(
require("yarp")
local start = yarp.Time_now()
local b = yarp.Bottle()
PortMonitor.create = function(options)
  local dest = options:find("destination"):asString()
  PortMonitor.setConstraint("e_ball and " .. (dest == "/motor/in" and "not e_line" or "x"))
  return true
end
)",
                             "ball.lua", kContext, {});
  ASSERT_TRUE(run.created) << run.error;
  EXPECT_EQ(run.constraint, "e_ball and not e_line");
  EXPECT_EQ(run.constraint_line, 7);
}

TEST(ScriptRunner, RunsAcceptOnSamples) {
  ScriptRun run = run_script(R"(
PortMonitor.accept = function(thing)
  local b = thing:asBottle()
  if b:get(0):asString() == "face" then
    PortMonitor.setEvent("e_" .. b:get(0):asString(), 0.5)
    return true
  end
  return false
end
)",
                             "f.lua", kContext, sample_bottles({"face"}, {}));
  ASSERT_TRUE(run.created) << run.error;
  ASSERT_GE(run.samples.size(), 2u);
  EXPECT_FALSE(run.samples[0].accepted);  // the empty bottle
  EXPECT_TRUE(run.samples[1].accepted);   // "face"
  ASSERT_EQ(run.samples[1].calls.size(), 1u);
  EXPECT_EQ(run.samples[1].calls[0].text, "e_face");
  EXPECT_EQ(run.samples[1].calls[0].number, 0.5);
}

TEST(ScriptRunner, CreateMustReturnTrue) {
  ScriptRun run = run_script("PortMonitor.create = function() end", "x.lua", kContext, {});
  EXPECT_TRUE(run.loaded);
  EXPECT_FALSE(run.created);
}

TEST(ScriptRunner, ErrorsNameTheScriptLine) {
  ScriptRun run = run_script("local x = nil\nx.y = 1\n", "bad.lua", kContext, {});
  EXPECT_FALSE(run.loaded);
  EXPECT_NE(run.error.find("bad.lua:2:"), std::string::npos) << run.error;
  ScriptRun stand_in =
      run_script("require('yarp')\nyarp.BufferedPortBottle()\n", "p.lua", kContext, {});
  EXPECT_NE(stand_in.error.find("stand-in"), std::string::npos) << stand_in.error;
  ScriptRun endless =
      run_script("PortMonitor.create = function() while true do end end", "loop.lua", kContext, {});
  EXPECT_FALSE(endless.created);
  EXPECT_NE(endless.error.find("instruction budget"), std::string::npos) << endless.error;
}

}  // namespace
}  // namespace arbc::yarp
