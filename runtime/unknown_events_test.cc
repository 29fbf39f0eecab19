// The unknown-after-start rule of distributed runs (RunOptions::unknown_until_fed) and the
// report of events that lapse because their source went silent.
#include <gtest/gtest.h>

#include "runtime/runtime_test_util.h"

namespace arbc {

using namespace std::chrono_literals;
namespace {

using testing::TestApp;

// Src.f feeds event `e` (lifetime 0.5 s) into Sink.x; rule `r` (Src.x -> Sink.x) reads it.
void feed_app(TestApp& t, const std::string& rule_constraint) {
  t.module("Src", {"out x: int", "out f: bool"});
  t.module("Sink", {"in x: int"});
  t.app.events.push_back({"e", 500ms, "Src.f", {}});
  t.connect("feed", "Src.f", "Sink.x", "false",
            "PortMonitor.accept = function(on)\n"
            "  if on then PortMonitor.setEvent('e') else PortMonitor.unsetEvent('e') end\n"
            "  return false\n"
            "end\n",
            model::ConnectionKind::Feed)
      .sets = {"e"};
  t.connect("r", "Src.x", "Sink.x", rule_constraint);
}

std::vector<double> delivery_times(Runtime& rt) {
  std::vector<double> out;
  for (const auto& g : TestApp::sink(rt).got) out.push_back(g.time);
  return out;
}

// `not e` looks true at start, but nothing is known about e: the rule waits for the feed.
TEST(UnknownEventsTest, ARuleWaitsForItsFeedAfterStart) {
  TestApp t;
  feed_app(t, "not e");
  RunOptions o;
  o.unknown_until_fed = true;
  auto rt = t.start(o);
  TestApp::publish_at(*rt, 0.1, "Src", "x", Value(1));      // unknown: not selected
  TestApp::publish_at(*rt, 0.2, "Src", "f", Value(false));  // the feed speaks: e is absent
  TestApp::publish_at(*rt, 0.3, "Src", "x", Value(2));      // selected
  rt->advance(1s);
  EXPECT_EQ(delivery_times(*rt), std::vector<double>{0.3});
  auto s = TestApp::stats_of(rt->stats(), "r");
  EXPECT_EQ(s.drops(DropReason::NotSelected), 1u);
}

// Time passing is no evidence (issue 39: a held bumper's publisher discovered late): with no
// message from the feed, e stays unknown past its lifetime, until the feed speaks.
TEST(UnknownEventsTest, TheLifetimeDoesNotEndTheUnknown) {
  TestApp t;
  feed_app(t, "not e");
  RunOptions o;
  o.unknown_until_fed = true;
  auto rt = t.start(o);
  for (double at : {0.1, 0.5, 0.7, 3.0}) TestApp::publish_at(*rt, at, "Src", "x", Value(1));
  TestApp::publish_at(*rt, 3.5, "Src", "f", Value(false));  // the feed speaks: e is absent
  TestApp::publish_at(*rt, 3.6, "Src", "x", Value(1));
  rt->advance(4s);
  EXPECT_EQ(delivery_times(*rt), std::vector<double>{3.6});
}

// `otherwise absent after 2s` (model::Event::fail_open_after): the spec lets the feed's silence
// count as absence once it has lasted that long since the start; before, the rule waits; the
// run says when it took the event as absent.
TEST(UnknownEventsTest, AFeedThatMayFailOpenCountsAsAbsentAfterItsSilence) {
  TestApp t;
  feed_app(t, "not e");
  t.app.events.back().fail_open_after = 2s;
  RunOptions o;
  o.unknown_until_fed = true;
  auto rt = t.start(o);
  std::vector<std::string> reports;
  rt->set_reporter([&](const std::string& line) { reports.push_back(line); });
  for (double at : {0.1, 1.9, 2.0, 2.5}) TestApp::publish_at(*rt, at, "Src", "x", Value(1));
  rt->advance(3s);
  EXPECT_EQ(delivery_times(*rt), (std::vector<double>{2.0, 2.5}));
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_NE(
      reports[0].find("event e taken as absent at 2.000 s: nothing from Src.f since the start"),
      std::string::npos)
      << reports[0];
}

// A feed that speaks before the silence is up ends the unknown by its message, as any feed does:
// a present event keeps the rule closed after the 2 s.
TEST(UnknownEventsTest, AFeedThatSpeaksIsBelievedBeforeItsSilenceIsUp) {
  TestApp t;
  feed_app(t, "not e");
  t.app.events.back().fail_open_after = 2s;
  t.app.events.back().lifetime = std::nullopt;  // set until unset
  RunOptions o;
  o.unknown_until_fed = true;
  auto rt = t.start(o);
  TestApp::publish_at(*rt, 0.5, "Src", "f", Value(true));  // e present
  for (double at : {1.0, 2.5}) TestApp::publish_at(*rt, at, "Src", "x", Value(1));
  rt->advance(3s);
  EXPECT_TRUE(delivery_times(*rt).empty());
}

// Without the option (a single-process run) nothing changes: `not e` holds at once.
TEST(UnknownEventsTest, OffByDefault) {
  TestApp t;
  feed_app(t, "not e");
  auto rt = t.start();
  TestApp::publish_at(*rt, 0.1, "Src", "x", Value(1));
  rt->advance(1s);
  EXPECT_EQ(delivery_times(*rt), std::vector<double>{0.1});
}

// A rule that reads no fed event is not held back.
TEST(UnknownEventsTest, RulesWithoutFedEventsAreUnaffected) {
  TestApp t;
  feed_app(t, "true");
  RunOptions o;
  o.unknown_until_fed = true;
  auto rt = t.start(o);
  TestApp::publish_at(*rt, 0.1, "Src", "x", Value(1));
  rt->advance(1s);
  EXPECT_EQ(delivery_times(*rt), std::vector<double>{0.1});
}

// The feed sets e at 1.0 and 1.2 and then goes silent: e lapses at 1.7 and that is reported
// once, although no message arrives to look at the container; an explicit unset later (the
// source speaks again) is not a lapse.
TEST(UnknownEventsTest, ASilentSourcesLapseIsReportedOnce) {
  TestApp t;
  feed_app(t, "e");
  RunOptions o;
  o.report_silent_lapses = true;
  auto rt = t.start(o);
  TestApp::publish_at(*rt, 1.0, "Src", "f", Value(true));
  TestApp::publish_at(*rt, 1.2, "Src", "f", Value(true));
  TestApp::publish_at(*rt, 3.0, "Src", "f", Value(true));
  TestApp::publish_at(*rt, 3.1, "Src", "f", Value(false));
  rt->advance(2500ms);
  bool reported_by_then = false;
  for (const std::string& r : t.reports) reported_by_then |= r.find("lapsed") != std::string::npos;
  EXPECT_TRUE(reported_by_then) << "the lapse at 1.7 was not reported by 2.5";
  rt->advance(5s);
  std::vector<std::string> lapses;
  for (const std::string& r : t.reports) {
    if (r.find("lapsed") != std::string::npos) lapses.push_back(r);
  }
  ASSERT_EQ(lapses.size(), 1u) << ::testing::PrintToString(t.reports);
  EXPECT_EQ(lapses[0], "event e at Sink.x lapsed at 1.700 s: nothing from Src.f for 500ms");
}

// A `by priority` hold that ends is not a silent source: hi delivers at 1.0 and its hold
// (act_hi, 1 s) lapses at 2.0 as it should; nothing is reported (it read "event act_hi at
// Sink.a lapsed at 2.000 s: nothing from Src.x for 1s"). A feed's event at the same port still is.
TEST(UnknownEventsTest, AHoldThatEndsIsNotASilentSource) {
  TestApp t;
  feed_app(t, "e");
  t.module("Src2", {"out y: int"});
  t.app.events.push_back({"act_hi", 1s, "", {}});
  model::Connection& hi = t.connect("hi", "Src2.y", "Sink.x", "true");
  hi.activity_event = "act_hi";
  hi.sets = {"act_hi"};
  RunOptions o;
  o.report_silent_lapses = true;
  auto rt = t.start(o);
  TestApp::publish_at(*rt, 1.0, "Src2", "y", Value(1));    // delivered: act_hi until 2.0
  TestApp::publish_at(*rt, 1.0, "Src", "f", Value(true));  // e until 1.5, then silent
  rt->advance(3s);
  EXPECT_EQ(TestApp::sink(*rt).got.size(), 1u);
  std::vector<std::string> lapses;
  for (const std::string& r : t.reports) {
    if (r.find("lapsed") != std::string::npos) lapses.push_back(r);
  }
  ASSERT_EQ(lapses.size(), 1u) << ::testing::PrintToString(t.reports);
  EXPECT_EQ(lapses[0], "event e at Sink.x lapsed at 1.500 s: nothing from Src.f for 500ms");
}

// The report writes its instant in the unit of the run, as `arbc run`'s last line and the run
// report do: in a run shorter than a second, ms (it read "0.600 s").
TEST(UnknownEventsTest, ALapseOfAShortRunIsInMilliseconds) {
  TestApp t;
  feed_app(t, "e");
  RunOptions o;
  o.report_silent_lapses = true;
  o.duration = 0.9;
  auto rt = t.start(o);
  TestApp::publish_at(*rt, 0.1, "Src", "f", Value(true));
  rt->advance(900ms);
  std::vector<std::string> lapses;
  for (const std::string& r : t.reports) {
    if (r.find("lapsed") != std::string::npos) lapses.push_back(r);
  }
  ASSERT_EQ(lapses.size(), 1u) << ::testing::PrintToString(t.reports);
  EXPECT_EQ(lapses[0], "event e at Sink.x lapsed at 600.0 ms: nothing from Src.f for 500ms");
}

}  // namespace
}  // namespace arbc
