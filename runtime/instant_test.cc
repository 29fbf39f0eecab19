// The runtime's instants are whole nanoseconds, compared exactly (core/instant.h): a throttle, a
// `by priority` hold and an event's lifetime end at their last nanosecond, with no tolerance, so
// a spacing the proof gives (`never two r within 1s`) holds for every pair of instants the
// runtime can produce. Before, a 1 ns "same instant" rule let deliveries 0.9999999995 s apart
// through a `throttle 1s` and a `hold 1s`.
#include <gtest/gtest.h>

#include "runtime/runtime_test_util.h"

namespace arbc {
namespace {

using namespace std::chrono_literals;
using testing::TestApp;

// Publishes Value(i) on its port `x` at the i-th of `times`, given in seconds through the module
// API (runtime/module.h), which the runtime turns into nanoseconds at one place.
class Timed : public Module {
 public:
  explicit Timed(std::vector<double> times) : times_(std::move(times)) {}
  void start() override {
    for (size_t i = 0; i < times_.size(); ++i)
      schedule(times_[i], [this, i] { publish("x", Value(static_cast<int64_t>(i))); });
  }

 private:
  std::vector<double> times_;
};

// The instants at which `connection` delivered, from the trace records (exact nanoseconds).
std::vector<Nanos> deliveries(const std::vector<TraceRecord>& records,
                              const std::string& connection) {
  std::vector<Nanos> out;
  for (const TraceRecord& r : records)
    if (r.kind == TraceKind::Deliver && r.connection == connection) out.push_back(r.t);
  return out;
}

// Any two of `times` are at least `gap` apart.
void expect_spaced(const std::vector<Nanos>& times, Nanos gap) {
  for (size_t i = 1; i < times.size(); ++i)
    EXPECT_GE(times[i] - times[i - 1], gap)
        << "deliveries at " << times[i - 1].count() << " ns and " << times[i].count() << " ns";
}

TEST(RuntimeInstantTest, AThrottleOfOneSecondDropsADeliveryOneNanosecondShort) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("rule", "Src.x", "Sink.x", "true").throttle = 1s;
  RunOptions o;
  std::vector<TraceRecord> records;
  o.trace_records = &records;
  auto rt = t.start(o);
  TestApp::publish_at(*rt, 1s, "Src", "x", Value(1));        // delivered
  TestApp::publish_at(*rt, 2s - 1ns, "Src", "x", Value(2));  // 999999999 ns after: throttled
  TestApp::publish_at(*rt, 2s, "Src", "x", Value(3));        // exactly 1 s after: delivered
  TestApp::publish_at(*rt, 3s - 1ns, "Src", "x", Value(4));  // throttled
  TestApp::publish_at(*rt, 3s + 1ns, "Src", "x", Value(5));  // delivered
  rt->advance(4s);
  EXPECT_EQ(deliveries(records, "rule"), (std::vector<Nanos>{1s, 2s, 3s + 1ns}));
  EXPECT_EQ(TestApp::stats_of(rt->stats(), "rule").drops(DropReason::Throttled), 2u);
}

// A module's time of 1 s + 0.9999999995 s is the instant it rounds to (core/instant.h): if that
// is 2 s the second delivery is exactly a second after the first, else it is throttled. Either
// way no two deliveries are less than the period apart, which the old tolerance broke.
TEST(RuntimeInstantTest, ThrottledDeliveriesAreAtLeastThePeriodApartWhateverTheModuleTimes) {
  const std::vector<double> offsets = {0.9999999994, 0.9999999995, 0.9999999996, 0.999999999,
                                       1.0,          1.000000001,  0.5};
  for (double offset : offsets) {
    TestApp t;
    t.registry.add_module("Timed", [offset] {
      return std::make_unique<Timed>(std::vector<double>{1.0, 1.0 + offset});
    });
    t.module("Timed", {"out x: int"});
    t.module("Sink", {"in x: int"});
    t.connect("rule", "Timed.x", "Sink.x", "true").throttle = 1s;
    RunOptions o;
    std::vector<TraceRecord> records;
    o.trace_records = &records;
    auto rt = t.start(o);
    rt->advance(3s);
    std::vector<Nanos> got = deliveries(records, "rule");
    expect_spaced(got, 1s);
    Nanos second = nanos_from_seconds(1.0 + offset);
    EXPECT_EQ(got.size(), second >= 2s ? 2u : 1u) << "offset " << offset;
  }
}

// `by priority`: hi's delivery at 1 s holds lo off for 1 s (its activity event's lifetime), up
// to the last nanosecond and not one past it.
TEST(RuntimeInstantTest, AHoldOfOneSecondEndsExactlyOneSecondAfterTheDelivery) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Src2", {"out y: int"});
  t.module("Sink", {"in a: int"});
  t.app.events.push_back({"act_hi", 1s, "", {}});
  model::Connection& hi = t.connect("hi", "Src.x", "Sink.a", "true");
  hi.activity_event = "act_hi";
  hi.sets = {"act_hi"};
  t.connect("lo", "Src2.y", "Sink.a", "not act_hi");
  RunOptions o;
  std::vector<TraceRecord> records;
  o.trace_records = &records;
  auto rt = t.start(o);
  TestApp::publish_at(*rt, 1s, "Src", "x", Value(1));         // hi delivered: act_hi until 2 s
  TestApp::publish_at(*rt, 1s, "Src2", "y", Value(2));        // held off
  TestApp::publish_at(*rt, 2s - 1ns, "Src2", "y", Value(3));  // held off: the last nanosecond
  TestApp::publish_at(*rt, 2s, "Src2", "y", Value(4));        // the hold has ended: delivered
  rt->advance(3s);
  EXPECT_EQ(deliveries(records, "hi"), (std::vector<Nanos>{1s}));
  EXPECT_EQ(deliveries(records, "lo"), (std::vector<Nanos>{2s}));
  EXPECT_EQ(TestApp::stats_of(rt->stats(), "lo").drops(DropReason::NotSelected), 2u);
}

// The same hold when the times come from a module in seconds: lo delivers only at an instant
// at least 1 s after hi's delivery.
TEST(RuntimeInstantTest, HeldOffDeliveriesAreAtLeastTheHoldAfterWhateverTheModuleTimes) {
  for (double offset : {0.9999999994, 0.9999999995, 0.9999999996, 1.0}) {
    TestApp t;
    t.registry.add_module(
        "Timed", [offset] { return std::make_unique<Timed>(std::vector<double>{1.0 + offset}); });
    t.module("Src", {"out x: int"});
    t.module("Timed", {"out x: int"});
    t.module("Sink", {"in a: int"});
    t.app.events.push_back({"act_hi", 1s, "", {}});
    model::Connection& hi = t.connect("hi", "Src.x", "Sink.a", "true");
    hi.activity_event = "act_hi";
    hi.sets = {"act_hi"};
    t.connect("lo", "Timed.x", "Sink.a", "not act_hi");
    RunOptions o;
    std::vector<TraceRecord> records;
    o.trace_records = &records;
    auto rt = t.start(o);
    TestApp::publish_at(*rt, 1s, "Src", "x", Value(1));
    rt->advance(3s);
    std::vector<Nanos> lo = deliveries(records, "lo");
    for (Nanos at : lo) EXPECT_GE(at - 1s, 1s) << "offset " << offset;
    EXPECT_EQ(lo.size(), nanos_from_seconds(1.0 + offset) >= 2s ? 1u : 0u) << "offset " << offset;
  }
}

// The case the old tolerance was for: a lifetime of 0.1 s set at 0.2 s. In doubles
// 0.2 + 0.1 > 0.3, so without the tolerance the event was still present at 0.3 s; in
// nanoseconds it is absent at exactly 0.3 s, also at a module's 0.1 + 0.2 (which rounds to it),
// and present a nanosecond before.
TEST(RuntimeInstantTest, ALifetimeOf100msSetAt200msEndsAtExactly300ms) {
  TestApp t;
  t.registry.add_module("Timed",
                        [] { return std::make_unique<Timed>(std::vector<double>{0.1 + 0.2}); });
  t.module("Src", {"out x: int", "out f: int"});
  t.module("Timed", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("feed", "Src.f", "Sink.x", "false",
            "PortMonitor.accept = function(m) PortMonitor.setEvent('e', 0.1) return true end\n",
            model::ConnectionKind::Feed);
  t.connect("rule", "Src.x", "Sink.x", "e");
  t.connect("late", "Timed.x", "Sink.x", "e");
  RunOptions o;
  std::vector<TraceRecord> records;
  o.trace_records = &records;
  auto rt = t.start(o);
  TestApp::publish_at(*rt, nanos_from_seconds(0.2), "Src", "f", Value(0));
  TestApp::publish_at(*rt, 300ms - 1ns, "Src", "x", Value(1));  // present: delivered
  TestApp::publish_at(*rt, 300ms, "Src", "x", Value(2));        // absent: not selected
  rt->advance(1s);
  EXPECT_EQ(deliveries(records, "rule"), (std::vector<Nanos>{300ms - 1ns}));
  EXPECT_EQ(TestApp::stats_of(rt->stats(), "late").drops(DropReason::NotSelected), 1u);
  for (const TraceRecord& r : records) {
    if (r.kind == TraceKind::Event && r.op == "set") {
      EXPECT_EQ(r.expiry, 300ms);
    }
  }
}

// A trace writes each instant exactly from its nanoseconds: 0.1 + 0.2 is 0.3, not
// 0.30000000000000004, and a nanosecond reads as one.
TEST(RuntimeInstantTest, TheTraceWritesInstantsExactly) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("rule", "Src.x", "Sink.x", "true");
  RunOptions o;
  o.trace_path = t.dir + "/trace.jsonl";
  auto rt = t.start(o);
  TestApp::publish_at(*rt, nanos_from_seconds(0.1 + 0.2), "Src", "x", Value(1));
  TestApp::publish_at(*rt, 1s + 1ns, "Src", "x", Value(2));
  rt->advance(2s);
  rt->shutdown();
  std::ifstream in(o.trace_path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("{\"t\":0.3,\"type\":\"deliver\""), std::string::npos) << text;
  EXPECT_NE(text.find("{\"t\":1.000000001,\"type\":\"deliver\""), std::string::npos) << text;
  EXPECT_EQ(text.find("0.30000000000000004"), std::string::npos) << text;
}

// A trig interval that rounds to no time at all would trig at one instant for ever: refused.
TEST(RuntimeInstantTest, ATrigIntervalUnderHalfANanosecondIsAnError) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("c", "Src.x", "Sink.x", "true",
            "PortMonitor.create = function() PortMonitor.setTrigInterval(0.0000000004) end\n"
            "PortMonitor.trig = function() end\n");
  auto rt = t.start();
  rt->advance(1s);
  std::string all;
  for (const std::string& r : t.reports) all += r + "\n";
  EXPECT_NE(all.find("setTrigInterval: interval must be at least 0.000000001 seconds"),
            std::string::npos)
      << all;
  EXPECT_TRUE(TestApp::stats_of(rt->stats(), "c").quarantined);
}

}  // namespace
}  // namespace arbc
