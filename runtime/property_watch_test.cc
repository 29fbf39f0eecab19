#include "runtime/property_watch.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

using Kind = model::TemporalProperty::Kind;

// The tests write times in seconds; the watch reads the runtime's nanoseconds.
Nanos ns(double seconds) { return nanos_from_seconds(seconds); }

TraceRecord deliver(double t, const std::string& rule, const std::string& port = "D.q") {
  TraceRecord r;
  r.kind = TraceKind::Deliver;
  r.t = ns(t);
  r.connection = rule;
  r.port = port;
  return r;
}

TraceRecord drop(double t, const std::string& rule) {
  TraceRecord r;
  r.kind = TraceKind::Drop;
  r.t = ns(t);
  r.connection = rule;
  r.reason = DropReason::NotSelected;
  return r;
}

TraceRecord event(double t, const std::string& op, const std::string& name,
                  const std::string& port = "D.q", double expiry = -1) {
  TraceRecord r;
  r.kind = TraceKind::Event;
  r.t = ns(t);
  r.op = op;
  r.event = name;
  r.owner = "feed";
  r.port = port;
  r.expiry = expiry < 0 ? kNever : ns(expiry);
  return r;
}

model::TemporalProperty property(Kind kind, const std::string& rule, double window = 0) {
  model::TemporalProperty p;
  p.kind = kind;
  p.port = "D.q";
  p.rule = rule;
  p.window = ns(window);
  p.condition = Constraint::constant(true);
  return p;
}

// The breach's text, or "" when the records keep the property up to `end`.
std::string judge(const model::TemporalProperty& p, const std::vector<TraceRecord>& records,
                  double end = 100) {
  PropertyWatch w(p, {"a", "b"});
  for (const TraceRecord& r : records) w.observe(r);
  w.finish(ns(end));
  return w.breach() ? w.breach()->what : "";
}

TEST(PropertyWatch, SpacingIsBrokenByTwoDeliveriesLessThanTheWindowApart) {
  model::TemporalProperty p = property(Kind::Spacing, "a", 1.0);
  EXPECT_EQ(judge(p, {deliver(0, "a"), deliver(1.0, "a"), deliver(2.5, "a")}), "");
  EXPECT_EQ(judge(p, {deliver(0, "a"), deliver(1.0, "a"), deliver(1.5, "a")}),
            "'a' delivered at 1s and at 1.5s");
  EXPECT_EQ(judge(p, {deliver(0, "a"), deliver(0.5, "b")}), "");  // another rule
  p.other = "b";                                                  // `never a within 1s after b`
  EXPECT_EQ(judge(p, {deliver(0, "b"), deliver(0.5, "a")}), "'a' delivered at 500ms, 'b' at 0s");
  EXPECT_EQ(judge(p, {deliver(0, "a"), deliver(0.5, "a")}), "");
}

TEST(PropertyWatch, AbsenceReadsThePortsOwnContainerWithLifetimes) {
  model::TemporalProperty p = property(Kind::Absence, "a");
  p.event = "e";
  EXPECT_EQ(judge(p, {event(0, "set", "e"), deliver(1, "a")}),
            "'a' delivered at 1s with e present");
  // The same name in another port's container is another fact (issue 38, events per container).
  EXPECT_EQ(judge(p, {event(0, "set", "e", "Other.p"), deliver(1, "a")}), "");
  EXPECT_EQ(judge(p, {event(0, "set", "e"), event(0.5, "unset", "e"), deliver(1, "a")}), "");
  // Set for 1s at 0: gone at 1s exactly, before the `expire` record comes.
  EXPECT_EQ(judge(p, {event(0, "set", "e", "D.q", 1.0), deliver(1.0, "a")}), "");
  EXPECT_NE(judge(p, {event(0, "set", "e", "D.q", 1.0), deliver(0.9, "a")}), "");
}

TEST(PropertyWatch, PrecedenceNeedsOneDeliveryOfTheOtherBeforeEach) {
  model::TemporalProperty p = property(Kind::Precedence, "a");
  p.other = "b";
  EXPECT_EQ(judge(p, {deliver(0, "b"), deliver(1, "a"), deliver(2, "b"), deliver(3, "a")}), "");
  EXPECT_EQ(judge(p, {deliver(0, "b"), deliver(1, "a"), deliver(3, "a")}),
            "'a' delivered at 3s with no delivery of 'b' since its last");
  EXPECT_NE(judge(p, {deliver(1, "a")}), "");
}

TEST(PropertyWatch, StabilityCountsSwitchesOfTheDeliverer) {
  model::TemporalProperty p = property(Kind::Stability, "", 1.0);
  EXPECT_EQ(judge(p, {deliver(0, "a"), deliver(0.2, "a"), deliver(0.5, "b"), deliver(1.5, "a")}),
            "");
  EXPECT_EQ(judge(p, {deliver(0, "a"), deliver(0.5, "b"), deliver(0.9, "a")}),
            "the deliverer switched at 500ms and at 900ms");
  EXPECT_EQ(judge(p, {deliver(0, "a"), deliver(0.5, "b", "Other.p"), deliver(0.9, "a")}), "");
}

TEST(PropertyWatch, ResponseWantsAnAnswerWithinTheWindowOfEachTrigger) {
  model::TemporalProperty p = property(Kind::Response, "a", 1.0);
  p.other = "b";
  EXPECT_EQ(judge(p, {deliver(0, "b"), deliver(0.5, "a")}), "");
  EXPECT_EQ(judge(p, {deliver(0, "b"), deliver(1.5, "a")}),
            "triggered at 0s, no delivery of 'a' by 1s");
  EXPECT_EQ(judge(p, {deliver(0, "b")}, 2.0), "triggered at 0s, no delivery of 'a' by 1s");
  EXPECT_EQ(judge(p, {deliver(0, "b")}, 0.5), "");  // the window ends after the run: not judged
  // A decision of the rule where `while` is false releases the trigger.
  p.condition = Constraint::event_ref("e");
  EXPECT_EQ(judge(p, {deliver(0, "b"), drop(0.5, "a")}, 2.0), "");
  EXPECT_NE(judge(p, {event(0, "set", "e"), deliver(0, "b"), drop(0.5, "a")}, 2.0), "");
}

TEST(PropertyWatch, ResponseStopsCountsFromTheLastTrigger) {
  model::TemporalProperty p = property(Kind::Response, "a", 1.0);
  p.other = "b";
  p.stops = true;
  EXPECT_EQ(judge(p, {deliver(0, "b"), deliver(0.8, "b"), deliver(1.6, "a")}), "");
  p.stops = false;
  EXPECT_NE(judge(p, {deliver(0, "b"), deliver(0.8, "b"), deliver(1.6, "a")}), "");
}

TEST(PropertyWatch, ResponseToAnEventAnsweredByThePort) {
  model::TemporalProperty p = property(Kind::Response, "", 0.04);
  p.event = "lost";
  EXPECT_EQ(judge(p, {event(0, "set", "lost"), deliver(0.03, "b")}), "");
  EXPECT_EQ(judge(p, {event(0, "set", "lost"), deliver(0.05, "b")}),
            "triggered at 0s, no delivery of D.q by 40ms");
  // Set again while present: no new trigger.
  EXPECT_EQ(judge(p, {event(0, "set", "lost"), deliver(0.03, "b"), event(0.05, "set", "lost")}),
            "");
}

}  // namespace
}  // namespace arbc
