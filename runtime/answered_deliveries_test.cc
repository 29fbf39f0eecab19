// The deliveries-not-yet-answered rule (docs/design.md#deliveries-not-yet-answered) in a
// mediator: the modules run in another process, reached through a transport that records what
// this process delivers and lets the test play their messages, each marked with how many
// deliveries its process had received when it was published (what the DDS transport reads
// from related_sample_identity).
#include <gtest/gtest.h>

#include "runtime/runtime_test_util.h"

namespace arbc {

using namespace std::chrono_literals;
namespace {

using testing::TestApp;

class RecordingTransport : public Transport {
 public:
  std::string name() const override { return "recording"; }
  bool open(const TransportPlan& plan, TransportSink* sink, std::string*) override {
    plan_ = plan;
    sink_ = sink;
    return true;
  }
  void publish(int, const Value&) override {}
  void deliver(int, const Delivery& d) override { delivered.push_back(d.time); }

  // A message of `port` (Module.port), as if it arrived now, answering `answered` deliveries.
  void arrive(const std::string& port, const Value& v, uint64_t answered) {
    for (const TransportPort& p : plan_.outputs) {
      if (p.qualified == port) sink_->from_source(p.index, v, answered);
    }
  }
  std::vector<double> delivered;  // the times of the commands sent to the arm

 private:
  TransportPlan plan_;
  TransportSink* sink_ = nullptr;
};

// Src.objects -> Arm.cmd when e_idle, mediated here; both modules run in the other process;
// the arm's status feeds e_idle for 0.5 s.
struct ArmMediator {
  TestApp t;
  std::shared_ptr<RecordingTransport> transport = std::make_shared<RecordingTransport>();
  std::unique_ptr<Runtime> rt;

  ArmMediator() {
    t.module("Src", {"out objects: int"});
    t.module("Arm", {"in cmd: int", "out status: bool"});
    t.app.events.push_back({"e_idle", 500ms, "Arm.status", {}});
    t.connect("take", "Src.objects", "Arm.cmd", "e_idle");
    model::Connection& feed = t.connect(
        "status_feed", "Arm.status", "Arm.cmd", "false",
        "PortMonitor.accept = function(idle)\n"
        "  if idle then PortMonitor.setEvent('e_idle') else PortMonitor.unsetEvent('e_idle') end\n"
        "  return true\n"
        "end\n",
        model::ConnectionKind::Feed);
    feed.sets = {"e_idle"};
    feed.unsets = {"e_idle"};
    RunOptions o;
    o.host = ModuleSet::none();
    o.mediate = ModuleSet::everything();
    o.transport = transport;
    rt = t.start(o);
  }
  void at(double time, std::function<void()> f) {
    rt->executor().post(nanos_from_seconds(time), std::move(f));
  }
  // Object lists and statuses from the other process, which had received `answered` commands.
  void objects(double time, uint64_t answered) {
    at(time, [this, answered] { transport->arrive("Src.objects", Value(int64_t{1}), answered); });
  }
  void status(double time, bool idle, uint64_t answered) {
    at(time, [this, idle, answered] { transport->arrive("Arm.status", Value(idle), answered); });
  }
};

TEST(AnsweredDeliveries, ARuleWaitsForTheRemoteModuleToAnswerItsDelivery) {
  ArmMediator m;
  ASSERT_TRUE(m.rt);
  m.status(0.0, true, 0);
  m.objects(0.1, 0);        // delivered: the arm said idle
  m.objects(0.2, 0);        // not: the arm has not answered the command of 0.1
  m.status(0.3, false, 1);  // the answer: busy
  m.objects(0.35, 1);       // not: busy
  m.status(0.4, true, 1);   // idle again
  m.objects(0.45, 1);       // delivered
  m.rt->advance(1s);
  EXPECT_EQ(m.transport->delivered, (std::vector<double>{0.1, 0.45}));
}

// A status published before the arm received the command, arriving late (a loaded machine, a
// slow network), says nothing of the arm after the command. Waiting one lifetime after the
// delivery is not enough: such a message sets the event again for a lifetime from its arrival.
TEST(AnsweredDeliveries, AStaleStatusArrivingLateDoesNotEndTheWait) {
  ArmMediator m;
  ASSERT_TRUE(m.rt);
  m.status(0.0, true, 0);
  m.objects(0.1, 0);       // delivered
  m.status(0.5, true, 0);  // stale: published before the arm had the command
  m.objects(0.65, 0);      // one lifetime after the delivery; e_idle only from stale news
  m.objects(0.9, 0);       // e_idle still set by the stale status (until 1.0)
  m.objects(1.05, 0);      // the stale entry lapsed: e_idle absent
  m.status(1.1, true, 1);  // the answer: idle
  m.objects(1.15, 1);      // delivered
  m.rt->advance(2s);
  EXPECT_EQ(m.transport->delivered, (std::vector<double>{0.1, 1.15}));
}

// A module that never speaks again does not block the rule for ever: once its entries have
// lapsed, the rule is judged on what is left (here: nothing, so `e_idle` is false, and an
// `idle` status that answers brings it back).
TEST(AnsweredDeliveries, ASilentModuleStopsBlockingOnceItsEntriesLapse) {
  ArmMediator m;
  ASSERT_TRUE(m.rt);
  m.status(0.0, true, 0);
  m.objects(0.1, 0);
  m.objects(0.7, 0);  // past the lifetime; e_idle lapsed at 0.5 anyway
  m.status(0.8, true, 1);
  m.objects(0.85, 1);
  m.rt->advance(1s);
  EXPECT_EQ(m.transport->delivered, (std::vector<double>{0.1, 0.85}));
}

}  // namespace
}  // namespace arbc
