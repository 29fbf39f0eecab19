#include "import/yarp/script_facts.h"

#include <gtest/gtest.h>

#include "import/yarp/lua_parser.h"

namespace arbc::yarp {
namespace {

ScriptFacts facts_of(const std::string& source) {
  std::string err;
  auto chunk = parse_lua(source, &err);
  EXPECT_TRUE(chunk) << err;
  return chunk ? analyse_script(*chunk) : ScriptFacts{};
}

using Pairs = std::vector<std::pair<std::string, std::string>>;
using Names = std::set<std::string>;

TEST(ScriptFacts, SelectorNeverLeavesBothSet) {
  ScriptFacts f = facts_of(R"(
PortMonitor.accept = function(thing)
  local cmd = thing:asBottle():get(0):asString()
  if cmd == "ball" then
    PortMonitor.unsetEvent("e_line")
    PortMonitor.setEvent("e_ball")
  elseif cmd == "line" then
    PortMonitor.setEvent("e_line")
    PortMonitor.unsetEvent("e_ball")
  end
  return false
end
PortMonitor.destroy = function() PortMonitor.unsetEvent("e_ball") PortMonitor.unsetEvent("e_line") end
)");
  ASSERT_TRUE(f.paths_ok) << f.paths_reason;
  EXPECT_FALSE(f.opaque);
  EXPECT_EQ(f.never_both, (Pairs{{"e_ball", "e_line"}}));
  EXPECT_FALSE(f.accept_may_accept);
  EXPECT_EQ(f.sets(), (Names{"e_ball", "e_line"}));
}

TEST(ScriptFacts, AnErrorBetweenSetAndUnsetBreaksTheSelector) {
  ScriptFacts f = facts_of(R"(
PortMonitor.accept = function(thing)
  if thing:asBottle():get(0):asString() == "ball" then
    PortMonitor.setEvent("e_ball")
    print(thing:asBottle():get(1):asString())   -- may raise: e_line is still set
    PortMonitor.unsetEvent("e_line")
  else
    PortMonitor.setEvent("e_line")
    PortMonitor.unsetEvent("e_ball")
  end
  return false
end
)");
  ASSERT_TRUE(f.paths_ok) << f.paths_reason;
  EXPECT_TRUE(f.never_both.empty());
}

TEST(ScriptFacts, AnnouncerSetsOnEveryAcceptingPath) {
  ScriptFacts f = facts_of(R"(
local LIFETIME = 0.5
PortMonitor.accept = function(thing)
  local b = thing:asBottle()
  if b:get(2):asFloat64() < 0.8 then return false end
  PortMonitor.setEvent("e_face", LIFETIME)
  PortMonitor.unsetEvent("e_search")
  return true
end
)");
  ASSERT_TRUE(f.paths_ok) << f.paths_reason;
  EXPECT_TRUE(f.accept_may_accept);
  EXPECT_EQ(f.must_set, Names{"e_face"});
  EXPECT_EQ(f.must_unset, Names{"e_search"});
}

TEST(ScriptFacts, MustSetNeedsEveryAcceptingPathAndAKnownLifetime) {
  ScriptFacts f = facts_of(R"(
PortMonitor.accept = function(thing)
  local b = thing:asBottle()
  if b:size() > 1 then
    PortMonitor.setEvent("a")
    PortMonitor.setEvent("b", b:get(0):asFloat64())
    return true
  end
  PortMonitor.setEvent("b", 1)
  while b:size() > 0 do PortMonitor.setEvent("c") b:pop() end
  return b
end
)");
  ASSERT_TRUE(f.paths_ok) << f.paths_reason;
  EXPECT_EQ(f.must_set, Names{});  // a: one path; b: unknown lifetime; c: the loop may not run
}

TEST(ScriptFacts, CallsIntoScriptCodeForgetEvents) {
  ScriptFacts f = facts_of(R"(
local function clear() PortMonitor.unsetEvent("e_a") end
PortMonitor.accept = function(thing)
  PortMonitor.setEvent("e_a")
  clear()
  return true
end
)");
  ASSERT_TRUE(f.paths_ok) << f.paths_reason;
  EXPECT_TRUE(f.must_set.empty());
  EXPECT_EQ(f.calls.size(), 2u);
  EXPECT_EQ(f.calls[0].callback, "(helper)");
  EXPECT_EQ(f.calls[1].callback, "accept");
}

TEST(ScriptFacts, LibraryAndYarpCallsKeepFacts) {
  ScriptFacts f = facts_of(R"(
PortMonitor.accept = function(thing)
  PortMonitor.setEvent("e_a")
  local s = string.format("%d", thing:asBottle():size())
  local t = yarp.now()
  return true
end
)");
  ASSERT_TRUE(f.paths_ok) << f.paths_reason;
  EXPECT_EQ(f.must_set, Names{"e_a"});
}

TEST(ScriptFacts, OpaqueWhenNamesAreComputed) {
  ScriptFacts f = facts_of(R"(
PortMonitor.accept = function(thing)
  PortMonitor.setEvent("e_" .. thing:asBottle():get(0):asString())
  return true
end
)");
  EXPECT_TRUE(f.opaque);
  EXPECT_NE(f.opaque_reason.find("not a string literal"), std::string::npos);
  EXPECT_EQ(f.opaque_line, 3);
  EXPECT_FALSE(f.paths_ok);
  EXPECT_TRUE(facts_of("local pm = PortMonitor\npm.setEvent('x')").opaque);
  EXPECT_TRUE(facts_of("PortMonitor['set' .. 'Event']('x')").opaque);
  EXPECT_TRUE(facts_of("load('PortMonitor.setEvent(\"x\")')()").opaque);
  EXPECT_FALSE(facts_of("require('yarp')").opaque);
}

// `local setEvent = PortMonitor.setEvent`, as the paper writes its listings: the calls
// through the alias are not seen, so the names cannot be known.
TEST(ScriptFacts, OpaqueWhenSetEventIsAliased) {
  ScriptFacts f = facts_of(R"(
local setEvent = PortMonitor.setEvent
PortMonitor.accept = function(thing)
  setEvent("e_face", 1.0)
  return true
end
)");
  EXPECT_TRUE(f.opaque);
  EXPECT_FALSE(f.opaque_names_only);
  EXPECT_EQ(f.opaque_line, 2);
  EXPECT_NE(f.opaque_reason.find("PortMonitor.setEvent is used as a value"), std::string::npos);
  EXPECT_TRUE(facts_of("PortMonitor.accept = function(t) local u = PortMonitor.unsetEvent "
                       "u('e') return true end")
                  .opaque);
  // Calling it, or defining callbacks, is not using it as a value.
  EXPECT_FALSE(facts_of("PortMonitor.accept = function(t) PortMonitor.setEvent('e') "
                        "return PortMonitor.trig ~= nil end")
                   .opaque);
}

// The paper's status monitor (its C3): computed names, and accept never returns true. The
// names are unknown, but it never delivers.
TEST(ScriptFacts, ComputedNamesStillTellWhatAcceptReturns) {
  ScriptFacts f = facts_of(R"(
PortMonitor.accept = function(thing)
  PortMonitor.setEvent(thing:asBottle():get(0):asString(), 0.5)
  return false
end
)");
  EXPECT_TRUE(f.opaque);
  EXPECT_TRUE(f.opaque_names_only);
  EXPECT_FALSE(f.paths_ok);
  EXPECT_FALSE(f.accept_may_accept);
  EXPECT_TRUE(f.must_set.empty());
  // Another reason to be opaque (code loaded at run time may replace accept) keeps it unknown.
  ScriptFacts g = facts_of(R"(
PortMonitor.accept = function(thing)
  PortMonitor.setEvent(thing:asBottle():get(0):asString(), 0.5)
  return false
end
load("x = 1")()
)");
  EXPECT_FALSE(g.opaque_names_only);
  EXPECT_TRUE(g.accept_may_accept);
}

TEST(ScriptFacts, RecordsCallsWithLinesAndArguments) {
  ScriptFacts f = facts_of(R"(PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_x")
  PortMonitor.setTrigInterval(0.1)
  return true
end
PortMonitor.trig = function() PortMonitor.setEvent("e_t", -1) end
)");
  ASSERT_EQ(f.calls.size(), 3u);
  EXPECT_EQ(f.calls[0].function, "setConstraint");
  EXPECT_EQ(f.calls[0].text, "e_x");
  EXPECT_EQ(f.calls[0].line, 2);
  EXPECT_EQ(f.calls[1].number, 0.1);
  EXPECT_EQ(f.calls[2].callback, "trig");
  EXPECT_EQ(f.calls[2].number, -1);
  EXPECT_EQ(f.callbacks, (Names{"create", "trig"}));
}

TEST(ScriptFacts, GotoDropsPathFacts) {
  ScriptFacts f = facts_of("PortMonitor.accept = function(t) goto x ::x:: return true end");
  EXPECT_FALSE(f.paths_ok);
  EXPECT_NE(f.paths_reason.find("goto"), std::string::npos);
}

TEST(ScriptFacts, AnEventUpdateAlwaysSetsIsSetAsTheConnectionDelivers) {
  ScriptFacts f = facts_of(R"(
PortMonitor.accept = function(thing) return true end
PortMonitor.update = function(thing)
  PortMonitor.setEvent("e_act", 1.0)
  return thing
end
PortMonitor.destroy = function() PortMonitor.unsetEvent("e_act") end
)");
  ASSERT_TRUE(f.paths_ok) << f.paths_reason;
  EXPECT_EQ(f.delivery_set, (Names{"e_act"}));
  EXPECT_TRUE(f.must_set.empty());
}

TEST(ScriptFacts, NotADeliveryEventWhenSetElsewhereOnSomePathsOrForever) {
  EXPECT_TRUE(facts_of(R"(
PortMonitor.accept = function(thing) PortMonitor.setEvent("e_act", 1.0) return true end
PortMonitor.update = function(thing) PortMonitor.setEvent("e_act", 1.0) return thing end
)")
                  .delivery_set.empty());
  EXPECT_TRUE(facts_of(R"(
PortMonitor.update = function(thing)
  if thing:asBottle():size() > 1 then PortMonitor.setEvent("e_act", 1.0) end
  return thing
end
)")
                  .delivery_set.empty());
  EXPECT_TRUE(facts_of(R"(
PortMonitor.update = function(thing) PortMonitor.setEvent("e_act") return thing end
)")
                  .delivery_set.empty());
}

}  // namespace
}  // namespace arbc::yarp
