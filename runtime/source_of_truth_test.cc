// What runs is what was proved (issue 13): the runtime takes each connection's constraint and
// each event's lifetime from the model (app.json), a monitor cannot replace a constraint, a
// monitor whose bytes differ from app.json's digest does not load, and a `by priority` rule's
// activity event is set only when the rule delivers.
#include <gtest/gtest.h>

#include <fstream>

#include "runtime/runtime_test_util.h"

namespace arbc {

using namespace std::chrono_literals;
namespace {

using testing::TestApp;

// Src.x -> Sink.x, constraint "e", with the given monitor.
TestApp app_with_monitor(const std::string& script) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("c", "Src.x", "Sink.x", "e", script);
  return t;
}

std::string create_error(TestApp& t) {
  std::string error;
  EXPECT_FALSE(Runtime::create(t.app, t.dir, {}, &error, t.registry));
  return error;
}

TEST(SourceOfTruthTest, AnotherConstraintInCreateIsBadInputAtLoad) {
  TestApp t = app_with_monitor(
      "PortMonitor.create = function(o)\n"
      "  PortMonitor.setConstraint('true')\n"
      "  return true\n"
      "end\n");
  // Named from here (under the app directory), so that the user can open it.
  EXPECT_EQ(
      create_error(t),
      t.dir +
          "/monitors/c.lua:2: setConstraint: \"true\" would replace the constraint of connection "
          "'c', \"e\" (app.json's, which arbc verify proves and the runtime installs); remove "
          "the call, or change the rule's `when` in the spec and rebuild");
}

TEST(SourceOfTruthTest, AnotherConstraintAtTopLevelOrCaughtByPcallIsBadInputToo) {
  TestApp top = app_with_monitor("PortMonitor.setConstraint('not e')\n");
  std::string error = create_error(top);
  EXPECT_NE(error.find(top.dir + "/monitors/c.lua:1: setConstraint: \"not e\" would replace the "
                                 "constraint of connection 'c', \"e\""),
            std::string::npos)
      << error;
  // The script swallows the error: the conflict is still reported, naming the file.
  TestApp caught = app_with_monitor(
      "PortMonitor.create = function(o)\n"
      "  pcall(PortMonitor.setConstraint, 'e or x')\n"
      "  return true\n"
      "end\n");
  error = create_error(caught);
  EXPECT_EQ(error.rfind(caught.dir + "/monitors/c.lua: setConstraint: \"e or x\" would replace", 0),
            0u)
      << error;
}

TEST(SourceOfTruthTest, TheSameConstraintIsAcceptedAndTheModelsRuns) {
  TestApp t = app_with_monitor(
      "PortMonitor.create = function(o)\n"
      "  PortMonitor.setConstraint('(e)')\n"  // the same formula, spelt differently
      "  return true\n"
      "end\n"
      "PortMonitor.accept = function(m)\n"
      "  assert(PortMonitor.getConstraint() == 'e')\n"
      "  if m == 2 then PortMonitor.setConstraint('true') end\n"  // refused at run time
      "  return true\n"
      "end\n");
  auto rt = t.start();
  ASSERT_TRUE(rt);
  TestApp::publish_at(*rt, 1, "Src", "x", Value(1));
  TestApp::publish_at(*rt, 2, "Src", "x", Value(2));
  TestApp::publish_at(*rt, 3, "Src", "x", Value(3));
  rt->advance(4s);
  auto s = TestApp::stats_of(rt->stats(), "c");
  // `e` is never present: nothing is selected, the refused call is the message's error.
  EXPECT_EQ(s.delivered, 0u);
  EXPECT_EQ(s.drops(DropReason::NotSelected), 2u);
  EXPECT_EQ(s.drops(DropReason::MonitorError), 1u);
  ASSERT_FALSE(t.reports.empty());
  EXPECT_NE(t.reports[0].find("would replace the constraint of connection 'c'"), std::string::npos)
      << t.reports[0];
}

TEST(SourceOfTruthTest, AMonitorWhoseBytesDifferFromTheDigestDoesNotLoad) {
  TestApp t = app_with_monitor("PortMonitor.accept = function(m) return true end\n");
  std::ofstream(t.dir + "/monitors/c.lua", std::ios::app) << "-- edited\n";
  std::string error = create_error(t);
  EXPECT_EQ(error.rfind(t.dir + "/monitors/c.lua: this monitor of connection 'c' is not the one "
                                "`arbc build` wrote",
                        0),
            0u)
      << error;
  EXPECT_NE(error.find("rebuild the app with `arbc build`"), std::string::npos) << error;
}

TEST(SourceOfTruthTest, SetEventWithoutALifetimeGetsTheOneAppJsonDeclares) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.app.events.push_back({"e", 500ms, "", {}});
  t.connect("c", "Src.x", "Sink.x", "true",
            "PortMonitor.accept = function(m)\n"
            "  PortMonitor.setEvent('e')\n"
            "  PortMonitor.setEvent('undeclared')\n"
            "  PortMonitor.setEvent('e_short', 0.25)\n"
            "  return true\n"
            "end\n");
  std::vector<TraceRecord> records;
  RunOptions o;
  o.trace_records = &records;
  auto rt = t.start(o);
  TestApp::publish_at(*rt, 1, "Src", "x", Value(1));
  rt->advance(2s);
  std::map<std::string, Nanos> expiry;
  for (const TraceRecord& r : records)
    if (r.kind == TraceKind::Event && r.op == "set") expiry[r.event] = r.expiry;
  EXPECT_EQ(expiry["e"], 1500ms);
  EXPECT_EQ(expiry["undeclared"], kNever);  // no lifetime anywhere: until unset
  EXPECT_EQ(expiry["e_short"], 1250ms);     // an explicit lifetime still wins
}

// hi (activity event act_hi, lifetime 1 s, throttle 0.5 s) outranks lo (`not act_hi`). Only
// hi's deliveries hold lo off: not a rejected message, not an unselected one, not a throttled
// one.
TEST(SourceOfTruthTest, TheActivityEventIsSetOnlyWhenTheRuleDelivers) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Src2", {"out y: int", "out w: int"});
  t.module("Sink", {"in a: int"});
  t.app.events.push_back({"act_hi", 1s, "", {}});
  model::Connection& hi = t.connect("hi", "Src.x", "Sink.a", "not e_stop",
                                    "PortMonitor.accept = function(m) return m > 0 end\n");
  hi.activity_event = "act_hi";
  hi.sets = {"act_hi"};
  hi.throttle = 500ms;
  t.connect("lo", "Src2.y", "Sink.a", "not act_hi");
  t.connect("stop", "Src2.w", "Sink.a", "false",
            "PortMonitor.accept = function(m)\n"
            "  if m == 1 then PortMonitor.setEvent('e_stop') else PortMonitor.unsetEvent('e_stop') "
            "end\n"
            "  return false\n"
            "end\n",
            model::ConnectionKind::Feed);
  auto rt = t.start();
  TestApp::publish_at(*rt, 0.0, "Src", "x", Value(-1));   // hi rejected
  TestApp::publish_at(*rt, 0.05, "Src2", "y", Value(0));  // lo delivered
  TestApp::publish_at(*rt, 0.1, "Src2", "w", Value(1));   // e_stop set
  TestApp::publish_at(*rt, 0.15, "Src", "x", Value(1));   // hi not selected
  TestApp::publish_at(*rt, 0.2, "Src2", "y", Value(0));   // lo delivered
  TestApp::publish_at(*rt, 0.25, "Src2", "w", Value(0));  // e_stop unset
  TestApp::publish_at(*rt, 0.3, "Src", "x", Value(1));    // hi delivered: act_hi until 1.3
  TestApp::publish_at(*rt, 0.4, "Src", "x", Value(1));    // hi throttled: act_hi not refreshed
  TestApp::publish_at(*rt, 1.25, "Src2", "y", Value(0));  // lo not selected
  TestApp::publish_at(*rt, 1.35, "Src2", "y", Value(0));  // lo delivered (would not at 1.4)
  rt->advance(2s);
  auto stats = rt->stats();
  auto h = TestApp::stats_of(stats, "hi");
  EXPECT_EQ(h.drops(DropReason::Rejected), 1u);
  EXPECT_EQ(h.drops(DropReason::NotSelected), 1u);
  EXPECT_EQ(h.drops(DropReason::Throttled), 1u);
  EXPECT_EQ(h.delivered, 1u);
  auto l = TestApp::stats_of(stats, "lo");
  EXPECT_EQ(l.delivered, 3u);
  EXPECT_EQ(l.drops(DropReason::NotSelected), 1u);
}

}  // namespace
}  // namespace arbc
