// The pieces of a Runtime, shared by runtime.cc (building and life cycle), message_path.cc
// and runtime_stats.cc. Not part of the public API.
#pragma once

#include <optional>
#include <random>

#include "runtime/bulk_drops.h"
#include "runtime/ring_queue.h"
#include "runtime/runtime.h"
#include "runtime/same_name.h"

namespace arbc {

// A generator seeded from the run's seed and a name (a module's, "environment"): deterministic
// and independent per name.
std::mt19937_64 seeded_generator(uint64_t seed, std::string_view who);
// FNV-1a: a stable hash (std::hash may differ between builds).
uint64_t stable_hash(std::string_view s);

// A module hosted in another process that connections mediated here deliver to: its recent
// deliveries (docs/design.md#deliveries-not-yet-answered); older ones no longer matter.
struct Runtime::RemoteModule {
  std::string name;
  struct Sent {
    uint64_t number = 0;  // among all deliveries into modules hosted elsewhere (1, 2, ...)
    Nanos time{0};
    uint64_t message = 0;  // the arrival it answered (Runtime::arrivals_)
  };
  std::deque<Sent> recent;
  // The feeds from its outputs that rules read: a delivery matters while one of them may still
  // show the module's state from before it.
  std::vector<const Connection*> feeds;
};

// An input port of a module instance, with its event container.
struct Runtime::InPort {
  int index = 0;          // TransportPort::index
  std::string qualified;  // "Module.port"
  std::string port;
  Module* module = nullptr;  // null: the module is not hosted here
  ModuleSlot* slot = nullptr;
  TypePtr type;
  bool mediated = false;           // the connections into it run here
  RemoteModule* remote = nullptr;  // its module, when hosted elsewhere
  EventContainer container;
  std::vector<Connection*> feeds;  // the feed connections into it
  // Feeds of delivery events (docs/design.md#delivery-events): from what this port delivers,
  // into the containers of the ports that read them; run in the task of each delivery.
  std::vector<Connection*> delivery_feeds;
  InputStats stats;  // what arrived mediated by another process
  BulkDrops bulk;    // its losses in bulk (RunOptions::report_bulk_drops)
};

// An output port and the connections leaving it, in model order.
struct Runtime::OutPort {
  int index = 0;  // TransportPort::index
  std::string qualified;
  std::string port;
  TypePtr type;
  bool hosted = false;
  RemoteModule* remote = nullptr;  // its module, when hosted elsewhere
  std::vector<Connection*> connections;
  std::set<std::string> reported;  // publish errors already reported
};

struct Runtime::Connection : MonitorHost {
  Nanos stamp_now() override;
  Runtime* runtime = nullptr;
  int index = 0;  // owner id in event containers
  std::string name;
  const model::Connection* model = nullptr;
  OutPort* source = nullptr;  // null for a delivery feed, whose stream is `delivered_from`
  InPort* destination = nullptr;
  InPort* delivered_from = nullptr;  // a delivery event's feed: the port whose deliveries it reads
  bool is_feed = false;

  std::unique_ptr<LuaMonitor> monitor;
  bool has_accept = false, has_update = false, has_trig = false;
  // create() runs at load; a failure or a `false` quarantines the connection at start().
  std::string create_failure;
  bool create_refused = false;
  // The constraint, installed from the model (app.json) and never replaced: what was proved.
  CompiledConstraint constraint;
  std::string constraint_text;
  // Set when the monitor called setConstraint with another constraint: bad input at load.
  std::string constraint_conflict;

  struct Queued {
    Value value;
    uint64_t answered = 0;  // TransportSink::from_source's
    uint64_t message = 0;   // its arrival's number (Runtime::arrivals_)
    Nanos arrived{0};       // Runtime::arrival_at_: its arrival's instant (or ROS 2 time)
  };
  RingQueue<Queued> queue;
  bool drain_posted = false;
  std::optional<Nanos> throttle;
  int list_bound = 0;  // model::Connection::list_bound: longer lists are dropped bad-value
  Nanos last_delivery = -kNever;  // none yet: no throttle period runs
  Nanos trig_interval{0};
  Executor::TaskId trig_task = 0;
  // Trig k runs at trig_start + k * trig_interval (as module ticks do): adding the interval to
  // the last run's time drifts (600 runs of 0.2 s land 1.2e-12 s late), and an event a trig
  // sets then outlives the instant its lifetime ends at (tests/drt/cases/selection-trig-drift).
  Nanos trig_start{0};
  uint64_t trig_runs = 0;

  // The unknown-after-start rule (RunOptions::unknown_until_fed): the feed-provided events the
  // constraint reads that are not known yet, each with its feed and lifetime. Emptied as they
  // become known; a feed is known once it processed a message since start (`fed`).
  struct UnknownEvent {
    std::string event;
    const Connection* feed = nullptr;
    // The deliveries-not-yet-answered rule's lifetime; for `unknown`, the event's
    // `otherwise absent after D` (model::Event::fail_open_after): none, unknown until fed.
    std::optional<Nanos> lifetime;
  };
  std::vector<UnknownEvent> unknown;
  // The deliveries-not-yet-answered rule: the events the constraint reads that a feed from a
  // module hosted elsewhere provides (that module may not have seen what was delivered to it).
  std::vector<UnknownEvent> feedback;
  // How many deliveries into modules hosted elsewhere the messages processed answer: the most
  // of any message so far (a feed), and the message being processed.
  uint64_t answered = 0, incoming_answered = 0;
  Nanos last_fed_at = -kNever;         // a feed's last accepted message (-kNever: none)
  uint64_t message = 0;                // the arrival number of the message being processed
  std::optional<Nanos> judging_since;  // its Queued::arrived, while it is processed
  bool fed = false;
  Nanos last_arrival = -kNever;            // none yet
  std::set<std::string> silence_reported;  // events reported lapsed since the last arrival

  int consecutive_errors = 0;
  bool quarantined = false;
  std::set<std::string> reported_errors;
  ConnectionStats stats;
  BulkDrops bulk;  // its losses in bulk (RunOptions::report_bulk_drops)

  // MonitorHost: PortMonitor calls from this connection's script.
  Nanos now() override;
  void set_event(std::string_view event, std::optional<Nanos> lifetime) override;
  void unset_event(std::string_view event) override;
  bool has_event(std::string_view event) override;
  bool set_constraint(std::string_view text, std::string* err) override;
  std::string get_constraint() override { return constraint_text; }
  void set_trig_interval(Nanos interval) override;
  void print(const std::string& line) override;
};

// One event of Connection::unknown: not known yet at `now` (its feed silent since the run's
// `start`, and not past its `otherwise absent after`); and how a drop's detail and the live
// status say so (unknown_events.cc).
bool still_unknown(const Runtime::Connection::UnknownEvent& u, Nanos now, Nanos start);
std::string unknown_text(const Runtime::Connection::UnknownEvent& u);

// The runtime's side of the transport seam (runtime/transport.h).
class Runtime::TransportLink : public TransportSink {
 public:
  explicit TransportLink(Runtime* runtime) : runtime_(runtime) {}
  void from_source(int out, const Value& v, uint64_t answered) override {
    runtime_->from_source(*runtime_->out_ports_[static_cast<size_t>(out)], v, answered);
  }
  void to_module(int in, const Delivery& d) override {
    runtime_->to_module(*runtime_->in_ports_[static_cast<size_t>(in)], d);
  }
  void lost(bool input, int index, DropReason reason, uint64_t count,
            const std::string& detail) override {
    runtime_->lost(input, index, reason, count, detail);
  }
  void report(const std::string& line) override { runtime_->report(line); }
  Executor& executor() override { return *runtime_->executor_; }

 private:
  Runtime* runtime_;
};

// Where plugin code (a module or the environment) runs: exceptions it throws stop there.
struct Runtime::PluginGuard {
  Runtime* runtime = nullptr;
  std::string name;             // the module's name, or "environment"
  const char* kind = "module";  // or "environment" (for BusyMarker)
  uint64_t errors = 0;
  std::set<std::string> reported_errors;

  // Runs fn; an exception escaping it is counted, traced and reported (once per distinct
  // text), and the run goes on. Returns false when fn threw.
  template <class F>
  bool guarded(const char* callback, F&& fn) {
    BusyScope busy(runtime->busy_, kind, name, callback);
    try {
      fn();
      return true;
    } catch (const std::exception& e) {
      runtime->plugin_failed(*this, callback, e.what());
    } catch (...) {
      runtime->plugin_failed(*this, callback, "an exception that is not a std::exception");
    }
    return false;
  }
};

// A module instance and its context.
class Runtime::ModuleSlot : public ModuleContext, public PluginGuard {
 public:
  std::unique_ptr<Module> module;
  // Searched by name on every publish: a module has a few outputs, and a scan costs less than
  // a map's string comparisons.
  std::vector<OutPort*> outputs;
  OutPort* output(std::string_view port) const {
    for (OutPort* out : outputs) {
      if (same_name(out->port, port)) return out;
    }
    return nullptr;
  }
  std::mt19937_64 random;
  Executor::TaskId tick_task = 0;
  std::set<std::string> reported;  // publish errors already reported

  // The module API's seconds (runtime/module.h); the runtime's instants are nanoseconds.
  double now() const override { return seconds_of(runtime->now()); }
  void publish(std::string_view port, Value v) override {
    runtime->publish_from(*this, port, std::move(v));
  }
  TimerId schedule(double delay, std::function<void()> fn) override;
  void cancel(TimerId id) override { runtime->executor_->cancel(id); }
  std::mt19937_64& rng() override { return random; }
  const std::string& scenario() const override { return runtime->scenario_; }
  uint64_t seed() const override { return runtime->options_.seed; }
  const std::string& module_name() const override { return name; }
  Environment* environment() override { return runtime->environment_.get(); }
  void log(std::string_view message) override;
};

class Runtime::EnvironmentSlot : public EnvironmentContext, public PluginGuard {
 public:
  std::mt19937_64 random;

  double now() const override { return seconds_of(runtime->now()); }
  TimerId schedule(double delay, std::function<void()> fn) override;
  void cancel(TimerId id) override { runtime->executor_->cancel(id); }
  std::mt19937_64& rng() override { return random; }
  const std::string& scenario() const override { return runtime->scenario_; }
  uint64_t seed() const override { return runtime->options_.seed; }
  void request_stop(std::string reason) override;
  Module* module(std::string_view name) override { return runtime->module(name); }
  void log(std::string_view message) override;
};

}  // namespace arbc
