#include "report/run_timeline.h"

#include <gtest/gtest.h>

#include "report/svg_timeline.h"
#include "runtime/runtime_test_util.h"

namespace arbc::report {

using namespace std::chrono_literals;
namespace {

// Times in seconds; an expiry below 0: none.
TraceRecord set(double t, const std::string& event, const std::string& owner, double expiry) {
  TraceRecord r;
  r.t = nanos_from_seconds(t);
  r.kind = TraceKind::Event;
  r.port = "P.in";
  r.op = "set";
  r.event = event;
  r.owner = owner;
  r.expiry = expiry < 0 ? kNever : nanos_from_seconds(expiry);
  return r;
}

TraceRecord unset(double t, const std::string& event, const std::string& owner) {
  TraceRecord r = set(t, event, owner, -1);
  r.op = "unset";
  return r;
}

std::vector<std::pair<double, double>> spans(const RunTimeline& timeline, const std::string& e) {
  std::vector<std::pair<double, double>> out;
  for (const EventLane& lane : timeline.events) {
    if (lane.event != e) continue;
    for (const Interval& i : lane.present) out.push_back({i.begin, i.end});
  }
  return out;
}

using Spans = std::vector<std::pair<double, double>>;

TEST(RunTimelineTest, RefreshExtendsAndUnsetEndsAnEntry) {
  RunTimeline t = build_run_timeline(
      {}, {set(1, "e", "a", 1.5), set(1.3, "e", "a", 1.8), unset(1.6, "e", "a")}, 10);
  EXPECT_EQ(spans(t, "e"), (Spans{{1, 1.6}}));
}

TEST(RunTimelineTest, ALapsedEntryEndsAtItsExpiryAndASetAfterwardsStartsAnew) {
  RunTimeline t = build_run_timeline(
      {}, {set(1, "e", "a", 1.5), set(2, "e", "a", 2.5), unset(3, "e", "a")}, 10);
  EXPECT_EQ(spans(t, "e"), (Spans{{1, 1.5}, {2, 2.5}}));
}

TEST(RunTimelineTest, AnEventIsPresentWhileAnyOwnerHoldsIt) {
  // a holds e from 1 (no lifetime) until it unsets it at 2.5; b holds it from 2 to 3.
  RunTimeline t = build_run_timeline(
      {}, {set(1, "e", "a", -1), set(2, "e", "b", 3), unset(2.5, "e", "a"), unset(2.7, "e", "c")},
      10);
  EXPECT_EQ(spans(t, "e"), (Spans{{1, 3}}));
}

TEST(RunTimelineTest, OpenEntriesEndAtTheEndOfTheRun) {
  RunTimeline t = build_run_timeline({}, {set(4, "e", "a", -1), set(9, "f", "a", 12)}, 10);
  EXPECT_EQ(spans(t, "e"), (Spans{{4, 10}}));
  EXPECT_EQ(spans(t, "f"), (Spans{{9, 10}}));
}

TEST(RunTimelineTest, LanesFollowTheGivenOrderAndUnknownConnectionsAreAppended) {
  TraceRecord d;
  d.t = 2s;
  d.kind = TraceKind::Deliver;
  d.connection = "b";
  TraceRecord x = d;
  x.kind = TraceKind::Drop;
  x.connection = "z";
  x.reason = DropReason::Throttled;
  TraceRecord q = x;
  q.kind = TraceKind::Quarantine;
  q.t = 3s;
  RunTimeline t = build_run_timeline({"a", "b"}, {d, x, q}, 5);
  ASSERT_EQ(t.connections.size(), 3u);
  EXPECT_EQ(t.connections[0].name, "a");
  EXPECT_EQ(t.connections[1].deliveries, std::vector<double>{2});
  EXPECT_EQ(t.connections[2].name, "z");
  ASSERT_EQ(t.connections[2].drops.size(), 1u);
  EXPECT_EQ(t.connections[2].drops[0].reason, DropReason::Throttled);
  EXPECT_EQ(t.connections[2].quarantined_at, 3);
}

TEST(RunTimelineTest, ABreachLineIsKeptWithItsClaimAndMarkedAcrossTheLanes) {
  TraceRecord b;
  b.t = 2500ms;
  b.kind = TraceKind::Breach;
  b.connection = "never two take within 1s";
  b.text = "broken at 2.5s: 'take' delivered at 2s and at 2.5s";
  RunTimeline t = build_run_timeline({"take"}, {b}, 5);
  ASSERT_EQ(t.breaches.size(), 1u);
  EXPECT_EQ(t.breaches[0].t, 2.5);
  EXPECT_EQ(t.breaches[0].claim, "never two take within 1s");
  std::string svg = connection_timeline_svg(t, 1);
  EXPECT_NE(svg.find("never two take within 1s broken (seen at 2.5"), std::string::npos) << svg;
  EXPECT_NE(svg.find(kBreachColor), std::string::npos);
}

// The reconstruction agrees with the runtime's own evaluator: a rule whose constraint is
// just `e`, probed every 10 ms, is delivered exactly while the rebuilt presence says `e` is
// present, and dropped as not-selected exactly while it says it is absent.
TEST(RunTimelineTest, PresenceAgreesWithTheRuntimesConstraintEvaluation) {
  arbc::testing::TestApp app;
  app.module("Src", {"out probe: int", "out flag: bool"});
  app.module("Sink", {"in x: int"});
  app.connect("feed", "Src.flag", "Sink.x", "false",
              "PortMonitor.accept = function(on)\n"
              "  if on then PortMonitor.setEvent('e', 0.35) else PortMonitor.unsetEvent('e') end\n"
              "  return false\n"
              "end\n",
              model::ConnectionKind::Feed);
  app.connect("rule", "Src.probe", "Sink.x", "e");
  std::vector<TraceRecord> records;
  RunOptions o;
  o.trace_records = &records;
  auto rt = app.start(o);
  // Flags: on at 1.0, 1.2, 2.0 (then lapses at 2.35), off at 1.4; on at 3.0, off at 3.1.
  for (auto [t, on] : std::vector<std::pair<double, bool>>{
           {1.0, true}, {1.2, true}, {1.4, false}, {2.0, true}, {3.0, true}, {3.1, false}}) {
    arbc::testing::TestApp::publish_at(*rt, t, "Src", "flag", Value(on));
  }
  // Probes at 5 ms past each 10 ms step, never on a flag instant.
  for (int k = 0; k < 400; ++k) {
    arbc::testing::TestApp::publish_at(*rt, 0.005 + k * 0.01, "Src", "probe", Value(k));
  }
  rt->advance(5s);
  rt->shutdown();
  RunTimeline t = build_run_timeline({"feed", "rule"}, records, 5);
  EXPECT_EQ(spans(t, "e"), (Spans{{1.0, 1.4}, {2.0, 2.35}, {3.0, 3.1}}));
  ASSERT_EQ(t.events.size(), 1u);
  auto present = [&](double at) {
    for (const Interval& i : t.events[0].present) {
      if (i.begin <= at && at < i.end) return true;
    }
    return false;
  };
  const ConnectionLane& rule = t.connections[1];
  EXPECT_GT(rule.deliveries.size(), 50u);
  for (double at : rule.deliveries) EXPECT_TRUE(present(at)) << at;
  for (const TimedDrop& d : rule.drops) {
    EXPECT_EQ(d.reason, DropReason::NotSelected);
    EXPECT_FALSE(present(d.t)) << d.t;
  }
  EXPECT_EQ(rule.deliveries.size() + rule.drops.size(), 400u);
}

}  // namespace
}  // namespace arbc::report
