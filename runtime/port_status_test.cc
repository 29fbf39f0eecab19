// The live view (runtime/port_status.h): why a rule is not selected, in words, and the runtime's
// view of its arbitrated ports as the message path would judge them.
#include "runtime/port_status.h"

#include <gtest/gtest.h>

#include "runtime/runtime_test_util.h"

namespace arbc {

using namespace std::chrono_literals;
namespace {

using testing::TestApp;

Constraint parsed(const std::string& text) {
  std::string error;
  std::optional<Constraint> c = parse_constraint(text, &error);
  EXPECT_TRUE(c) << error;
  return c ? *c : Constraint{};
}

std::string why(const std::string& constraint, std::set<std::string> present) {
  return why_false(
      parsed(constraint), [&](const std::string& e) { return present.contains(e); },
      [](const std::string& e) { return e == "act_dock" ? std::string("dock") : std::string(); });
}

TEST(WhyFalseTest, NamesTheEventsThatMakeItFalse) {
  EXPECT_EQ(why("not e_bumped and e_ok", {"e_bumped"}), "e_bumped present, e_ok absent");
  EXPECT_EQ(why("not e_bumped and e_ok", {"e_ok", "e_bumped"}), "e_bumped present");
  EXPECT_EQ(why("not e_bumped and e_ok", {"e_ok"}), "");  // true: nothing to say
  EXPECT_EQ(why("e_joy or e_teleop", {}), "e_joy absent, e_teleop absent");
  EXPECT_EQ(why("not (a and b)", {"a", "b"}), "a present, b present");
  // A lock (docs/language.md#locks): engaged, or not heard.
  EXPECT_EQ(why("not (l_engaged or not l_heard)", {}), "l_heard absent");
  EXPECT_EQ(why("not (l_engaged or not l_heard)", {"l_engaged", "l_heard"}), "l_engaged present");
  EXPECT_EQ(why("false", {}), "its `when` is false");
}

TEST(WhyFalseTest, APrioritysActivityEventIsAHold) {
  EXPECT_EQ(why("not act_dock and not e_bumped", {"act_dock"}), "held by dock's hold");
  EXPECT_EQ(why("not act_nav", {"act_nav"}), "act_nav present");  // no rule's: an event
}

// joy (Src.y, when e) and nav (Src.x, when not e) into Sink.x; the feed from Src.f sets e for
// 500 ms on true.
void two_rules(TestApp& t) {
  t.module("Src", {"out x: int", "out y: int", "out f: bool"});
  t.module("Sink", {"in x: int"});
  t.app.events.push_back({"e", 500ms, "Src.f", {}});
  t.connect("feed", "Src.f", "Sink.x", "false",
            "PortMonitor.accept = function(on)\n"
            "  if on then PortMonitor.setEvent('e') else PortMonitor.unsetEvent('e') end\n"
            "  return false\n"
            "end\n",
            model::ConnectionKind::Feed)
      .sets = {"e"};
  t.connect("joy", "Src.y", "Sink.x", "e");
  t.connect("nav", "Src.x", "Sink.x", "not e");
  model::ArbitratedPort port;
  port.port = "Sink.x";
  port.rules = {"joy", "nav"};
  t.app.arbitrated_ports.push_back(port);
}

// The port's status at `at`, taken on the runtime's thread.
PortStatus status_at(Runtime& rt, Nanos at) {
  PortStatus out;
  rt.executor().post(at, [&] {
    std::vector<PortStatus> all = rt.port_status();
    EXPECT_EQ(all.size(), 1u);
    if (!all.empty()) out = all[0];
  });
  rt.advance(at);
  return out;
}

const RuleStatus& rule(const PortStatus& p, const std::string& name) {
  for (const RuleStatus& r : p.rules)
    if (r.rule == name) return r;
  static RuleStatus none;
  ADD_FAILURE() << "no rule " << name;
  return none;
}

TEST(PortStatusTest, TheSelectedRuleAndWhyTheOthersAreNot) {
  TestApp t;
  two_rules(t);
  auto rt = t.start();
  TestApp::publish_at(*rt, 0.1, "Src", "x", Value(1));
  PortStatus p = status_at(*rt, 200ms);
  EXPECT_EQ(p.selected, "nav");
  EXPECT_EQ(p.level, StatusLevel::Ok);
  EXPECT_EQ(p.message, "nav selected");
  EXPECT_EQ(rule(p, "joy").blocked, "e absent");
  EXPECT_EQ(rule_state_text(rule(p, "nav"), 200ms), "selected, delivered 100ms ago");
  EXPECT_EQ(p.arrived, 1u);
  EXPECT_EQ(p.delivered, 1u);

  // The feed says e: nav may no longer deliver, joy may, but nothing came from it yet.
  TestApp::publish_at(*rt, 0.3, "Src", "f", Value(true));
  p = status_at(*rt, 350ms);
  EXPECT_EQ(p.selected, "");
  EXPECT_EQ(rule(p, "nav").blocked, "e present");
  EXPECT_EQ(rule_state_text(rule(p, "joy"), 350ms), "may deliver; nothing from Src.y yet");
  EXPECT_EQ(p.message, "none selected; joy may deliver");

  TestApp::publish_at(*rt, 0.4, "Src", "y", Value(2));
  p = status_at(*rt, 450ms);
  EXPECT_EQ(p.selected, "joy");
  EXPECT_EQ(p.last_rule, "joy");
  // e lapses at 0.8 s: nothing may deliver joy's next message, and nav is back.
  p = status_at(*rt, 900ms);
  EXPECT_EQ(p.selected, "");
  EXPECT_EQ(p.message, "none selected; nav may deliver");
  EXPECT_EQ(rule(p, "joy").blocked, "e absent");
  EXPECT_EQ(rule_state_text(rule(p, "nav"), 900ms),
            "may deliver; last message from Src.x 800ms ago");
}

// After a start in a distributed run nothing is known of e: every rule is blocked, and the
// port warns.
TEST(PortStatusTest, UnknownSinceStartBlocksAndWarns) {
  TestApp t;
  two_rules(t);
  RunOptions o;
  o.unknown_until_fed = true;
  auto rt = t.start(o);
  PortStatus p = status_at(*rt, 100ms);
  EXPECT_EQ(rule(p, "nav").blocked, "unknown since start: e (nothing from Src.f yet)");
  EXPECT_EQ(p.level, StatusLevel::Warn);
  EXPECT_EQ(p.message, "no rule may deliver");
  EXPECT_NE(status_lines({p}, 100ms).find("Sink.x  WARN  no rule may deliver | joy: unknown"),
            std::string::npos)
      << status_lines({p}, 100ms);
}

// `by priority`: dock's delivery holds nav off for the hold, and the status says so.
TEST(PortStatusTest, AHoldIsNamed) {
  TestApp t;
  t.module("Src", {"out x: int", "out y: int"});
  t.module("Sink", {"in x: int"});
  t.app.events.push_back({"act_dock", 1s, "", {}});
  t.connect("dock", "Src.y", "Sink.x", "true").activity_event = "act_dock";
  t.app.connections.back().sets = {"act_dock"};
  t.connect("nav", "Src.x", "Sink.x", "not act_dock");
  model::ArbitratedPort port;
  port.port = "Sink.x";
  port.by_priority = true;
  port.rules = {"dock", "nav"};
  t.app.arbitrated_ports.push_back(port);
  auto rt = t.start();
  TestApp::publish_at(*rt, 0.1, "Src", "y", Value(1));
  PortStatus p = status_at(*rt, 200ms);
  EXPECT_EQ(p.selected, "dock");
  EXPECT_EQ(rule(p, "nav").blocked, "held by dock's hold");
  p = status_at(*rt, 1200ms);  // the hold is over
  EXPECT_EQ(rule(p, "nav").blocked, "");
}

// A rule whose accept sets an event its `when` reads (an imported twist_mux input reads its own
// activity): its next message finds the event present, so the event's absence now blocks
// nothing and the status does not say it does.
TEST(PortStatusTest, WhatTheNextMessageSetsIsPresentForIt) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.app.events.push_back({"x_active", 500ms, "", {}});
  model::Connection& r = t.connect("x", "Src.x", "Sink.x", "x_active",
                                   "PortMonitor.accept = function(m)\n"
                                   "  PortMonitor.setEvent('x_active', 0.5)\n"
                                   "  return true\n"
                                   "end\n");
  r.sets = r.must_set = {"x_active"};
  model::ArbitratedPort port;
  port.port = "Sink.x";
  port.rules = {"x"};
  t.app.arbitrated_ports.push_back(port);
  auto rt = t.start();
  PortStatus p = status_at(*rt, 100ms);
  EXPECT_EQ(rule(p, "x").blocked, "");
  EXPECT_EQ(p.message, "none selected; x may deliver");
  TestApp::publish_at(*rt, 0.2, "Src", "x", Value(1));
  p = status_at(*rt, 300ms);
  EXPECT_EQ(p.selected, "x");  // and its message was delivered, as the status foretold
  EXPECT_EQ(p.delivered, 1u);
}

// RunOptions::on_status: every period from the start, and once at the end (unless a period
// ended there).
TEST(PortStatusTest, CalledEveryPeriodAndAtTheEnd) {
  TestApp t;
  two_rules(t);
  RunOptions o;
  o.duration = 1;
  o.status_period = 300ms;
  std::vector<Nanos> calls;
  o.on_status = [&](Nanos t, const std::vector<PortStatus>& ports) {
    calls.push_back(t);
    EXPECT_EQ(ports.size(), 1u);
  };
  std::string error;
  auto rt = Runtime::create(t.app, t.dir, o, &error, t.registry);
  ASSERT_TRUE(rt) << error;
  rt->run();
  EXPECT_EQ(calls, (std::vector<Nanos>{300ms, 600ms, 900ms, 1000ms}));
  calls.clear();
  o.duration = 0.9;
  rt = Runtime::create(t.app, t.dir, o, &error, t.registry);
  ASSERT_TRUE(rt) << error;
  rt->run();
  EXPECT_EQ(calls, (std::vector<Nanos>{300ms, 600ms, 900ms}));  // not 900ms twice
}

}  // namespace
}  // namespace arbc
