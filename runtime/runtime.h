// A running application: modules from the registry, connections with their Lua monitors,
// one event container per input port, an executor and a trace (docs/design.md#runtime).
//
// The message path, for a message on connection c into port P at time t:
//   1. c's accept(msg) runs (it may set and unset events); false: drop `rejected`.
//   2. c's constraint is evaluated on P's container at t; false: drop `not-selected`
//      (`feed` for feed connections, whose constraint is false by design).
//   3. throttle: a delivery on c less than its throttle period ago: drop `throttled`.
//   4. c's update(msg) runs; its result is delivered to P's module, and c's activity event
//      (`by priority`) is set for its lifetime.
// What runs is what was proved: constraints and event lifetimes come from the model
// (app.json), monitors may not replace a constraint, and a monitor whose bytes differ from
// the digest app.json records does not load.
// Script errors drop the message (`monitor-error`); a connection whose callbacks fail
// `quarantine_after` times in a row is quarantined: its monitor is destroyed and its further
// messages are dropped (`quarantined`). Each connection keeps a bounded FIFO queue
// (`queue-full` drops beyond it), so messages on one connection keep their order. A value
// that does not fit its output port's type is dropped on each connection from the port
// (`bad-type`). An exception thrown by a module or the environment is caught, counted
// (plugin_stats), traced and reported; the run goes on.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/compiled_constraint.h"
#include "runtime/busy_marker.h"
#include "runtime/drop_reason.h"
#include "runtime/event_container.h"
#include "runtime/executor.h"
#include "runtime/lua_monitor.h"
#include "runtime/mediator_memory.h"
#include "runtime/module.h"
#include "runtime/port_status.h"
#include "runtime/trace.h"
#include "runtime/transport.h"

namespace arbc {

struct RunOptions {
  std::string scenario;  // empty: the environment's first scenario, else "default"
  uint64_t seed = 1;
  double duration = 60;  // seconds of (simulated or wall) time
  bool realtime = false;
  double time_scale = 1;  // realtime: run time is time_scale times wall time
  // Where each module runs (docs/design.md#transports): the modules this process hosts (their
  // plugin instances run here; an environment is set up only when some module is hosted), and
  // the modules it mediates (the connections into their input ports run here; none: the
  // hosted modules). The in-process transport needs every module in both.
  ModuleSet host;
  std::optional<ModuleSet> mediate;
  // Where messages between ports go; nullptr: make_inproc_transport().
  std::shared_ptr<Transport> transport;
  // After a (re)start this process knows no event: a rule whose constraint reads an event that
  // a feed provides is not selected until that feed has processed a message since start (time
  // passing is no evidence: docs/design.md#unknown-events-after-a-start). On for distributed
  // runs, where the modules do not start with the mediator.
  bool unknown_until_fed = false;
  // Report (once per silence) an event that lapses because its feed's source sent nothing for
  // its lifetime: in a distributed run, the sign that a peer is gone.
  bool report_silent_lapses = false;
  // Say (one line, when it starts) that a connection or a mediated input loses messages in
  // bulk: BulkDrops::kThreshold losses of one reason within a second of run time; said again
  // only after a second without one (runtime/bulk_drops.h). On for distributed runs.
  bool report_bulk_drops = false;
  // The file the app's model was read from ("out/app/app.json"). Errors of Runtime::create about
  // the model's content (a connection between ports the app lacks) name it ("app NAME" when it
  // is empty); the others name what they are about (a plugin, a monitor file, the trace file, the
  // transport), not the model.
  std::string app_file;
  std::string trace_path;  // empty: no trace
  // Not null: every trace record is also appended here (for `arbc run --report`); the
  // vector must outlive the run.
  std::vector<TraceRecord>* trace_records = nullptr;
  // Not empty: every trace record is also given to it, on the thread that makes it (the runtime
  // checks of `arbc run`, runtime/claim_watch.h).
  Trace::Watch trace_watch;
  // Not empty: called once with the instant the run's time starts, after the transport's wait
  // for peers (the start that `given M.p every D` counts from).
  std::function<void(Nanos)> on_start;
  // Not empty: the file this mediator keeps its memory of its own deliveries in, read at start
  // when it exists and written after each delivery (runtime/mediator_memory.h); with the
  // runtime checks' share of it.
  std::string state_path;
  MemoryHooks checks_memory;
  // Not empty: called once at shutdown, with the instant the run ended, before the trace is
  // closed (the runtime checks judge what only the end shows and write it into the trace).
  std::function<void(Nanos, Trace&)> on_finish;
  // Not empty: the live view (`arbc run --status`): called on the runtime's thread with each
  // arbitrated port mediated here (Runtime::port_status), every status_period of run time from
  // the start, and once more at the end. A transport that carries the status
  // (Transport::carries_status: DDS's status topics) gets it at the same instants.
  std::function<void(Nanos, const std::vector<PortStatus>&)> on_status;
  Nanos status_period = std::chrono::milliseconds(250);
  SandboxLimits limits;
  size_t queue_capacity = 256;  // messages per connection
  int quarantine_after = 5;     // consecutive failing callbacks
  // Not null: once *interrupt is true (a signal handler sets it), the run stops as soon as it
  // can: the executor before its next task, a monitor callback at its next check (its message
  // is dropped as `monitor-error`, "interrupted"); stop_reason() is then "interrupted".
  const std::atomic<bool>* interrupt = nullptr;
};

// Counters of one connection, for the end-of-run table and tests.
struct ConnectionStats {
  std::string name, source, destination;
  size_t model_index = 0;  // the connection's position in the app's (app.json's) connections
  uint64_t arrived = 0, delivered = 0, errors = 0;
  uint64_t pending = 0;  // still queued when the run ended (arrived = delivered + drops + pending)
  std::array<uint64_t, kDropReasonCount> dropped{};
  bool quarantined = false;
  uint64_t drops(DropReason r) const { return dropped[static_cast<int>(r)]; }
};

// Messages for an input of a module hosted here that another process mediates: what arrived
// through the transport and what it lost before delivery (queue-full, bad-type,
// lost-in-transit).
struct InputStats {
  std::string port;                     // "Module.port"
  uint64_t arrived = 0, delivered = 0;  // arrived = delivered + drops
  std::array<uint64_t, kDropReasonCount> dropped{};
  uint64_t drops(DropReason r) const { return dropped[static_cast<int>(r)]; }
};

// Failures of plugin code: exceptions thrown by a module's callbacks (start, on_delivery,
// tick, timers, stop) or by the environment. The run goes on after each.
struct PluginStats {
  std::string name;  // the module's name, or "environment"
  uint64_t errors = 0;
};

class Runtime {
 public:
  // Instantiates the app: modules (from registry), monitors (files relative to app_dir),
  // constraints, environment. Returns nullptr and sets *error (what is wrong, what to do; one
  // line per problem; see RunOptions::app_file for what it names) on failure. Does not start
  // anything yet.
  static std::unique_ptr<Runtime> create(const model::App& app, const std::string& app_dir,
                                         const RunOptions& options, std::string* error,
                                         Registry& registry = Registry::global());
  ~Runtime();

  // Whole run: start(), advance to options.duration (or an early stop), shutdown().
  void run();
  // Sets up the environment, creates monitors, starts modules and their ticks.
  void start();
  // Runs the executor until time `until` or a stop request.
  void advance(Nanos until);
  // Ends the run after the task that runs now (on the executor's thread: a trace watch, say);
  // stop_reason() is then `reason`, unless the run was already stopping.
  void request_stop(const std::string& reason);
  // Stops modules, destroys monitors, finishes the environment, closes the trace.
  void shutdown();

  // Injects a message as if module.port (an output port) had published it.
  void publish(std::string_view module, std::string_view port, Value v);

  Nanos now() const { return executor_->now(); }
  // The run's clock as ROS 2 time, what age() measures stamps against (message_path.cc).
  Nanos stamp_clock() const;
  Executor& executor() { return *executor_; }
  Module* module(std::string_view name);
  Environment* environment() { return environment_.get(); }
  const std::string& scenario() const { return scenario_; }
  const std::string& stop_reason() const { return stop_reason_; }
  bool stopped_early() const { return !stop_reason_.empty(); }
  std::vector<ConnectionStats> stats() const;
  // Each arbitrated port mediated here: its selected rule, why each other rule is not, its
  // counters (runtime/port_status.h). On the runtime's thread (RunOptions::on_status).
  std::vector<PortStatus> port_status();
  // Inputs of hosted modules mediated by another process (empty in a single-process run).
  std::vector<InputStats> input_stats() const;
  // The transport's name ("inproc", "dds") and its end-of-run lines.
  std::string transport_name() const;
  std::string transport_summary() const;
  TransportStatus transport_status() const;
  // A table of the counters, one row per connection.
  std::string stats_table() const;
  // Where run-time problems are reported (default: stderr). Each distinct script error is
  // reported once per connection.
  void set_reporter(std::function<void(const std::string&)> reporter) {
    reporter_ = std::move(reporter);
  }
  // Memory used by each monitor's Lua state, by connection name.
  std::map<std::string, size_t> monitor_memory() const;
  // Exceptions caught from each module (in app order), then from the environment if any.
  std::vector<PluginStats> plugin_stats() const;

  // What the executor thread runs now; any thread may ask (a watchdog).
  BusyMarker::Snapshot busy() const { return busy_.snapshot(); }
  // "the monitor of connection 'take', in accept", "module 'Arm', in on_delivery": `b` in words.
  static std::string describe(const BusyMarker::Snapshot& b);
  // For a watchdog thread when the executor thread is stuck in a callback and the run cannot
  // shut down: writes `why` as a last log record and closes the trace.
  void abandon_trace(const std::string& why);

  struct RemoteModule;
  struct InPort;
  struct OutPort;
  struct Connection;
  struct PluginGuard;
  class ModuleSlot;
  class EnvironmentSlot;
  class TransportLink;

 private:
  Runtime();
  // The steps of create(), in order; each false with *error on bad input.
  bool create_environment(const Registry& registry, std::string* error);
  bool create_modules(const Registry& registry, std::string* error);
  bool create_module_slot(const model::Module& m, const ModuleFactory& factory, std::string* error);
  void create_ports(const model::Module& m, ModuleSlot* slot);
  bool create_connections(std::string* error);
  bool attach_delivery_feed(Connection& c, const std::string& where, std::string* error);
  bool create_connection(size_t i, const std::string& display_name,
                         std::span<const model::Connection* const> into, std::string* error);
  bool open_trace(std::string* error);
  bool open_transport(std::string* error);
  // Routes a message published on `out` to each connection from it mediated here.
  void from_source(OutPort& out, const Value& v, uint64_t answered);
  // Hands a mediated delivery to the hosted module of input `in`.
  void to_module(InPort& in, const Delivery& d);
  void lost(bool input, int index, DropReason reason, uint64_t count, const std::string& detail);
  std::string input_table() const;
  std::string connection_table() const;
  // The unknown-after-start rule: which feed-provided events each rule's constraint reads.
  void collect_unknown_events();
  // Removes what is known by now from c.unknown; false (with *why) while something is not.
  bool knows_events_of(Connection& c, std::string* why);
  // The deliveries-not-yet-answered rule (answered_deliveries.cc): which events each rule reads
  // from feeds of modules hosted elsewhere; whether all are answered at t (else *why); and the
  // bookkeeping of a delivery into a module hosted elsewhere.
  void collect_feedback_events();
  bool answered_events_of(Connection& c, Nanos t, std::string* why);
  void delivered_to_remote(RemoteModule& m, Nanos t, uint64_t message);
  // An event entry lapsed in `in`'s container; reports it when its source went silent.
  void lapsed(InPort& in, int event, int owner, Nanos expiry);
  // Looks at every mediated container each `period` s, so that lapses are seen (and reported)
  // when they happen even when no message arrives any more.
  void watch_lapses(Nanos period);
  // The live view (runtime_status.cc): what keeps c from delivering now ("" nothing), and the
  // periodic call of RunOptions::on_status from `at` on.
  std::string blocked_now(Connection& c, Nanos t);
  void post_status(Nanos at);
  void report(const std::string& line);
  // An instant of this run as its reports write it: in the unit of the run's duration, as
  // `arbc run`'s last line and the run report do (core/time_format.h).
  std::string run_time_text(Nanos t) const;
  struct Passing;
  static bool after_accept(void* passing, bool accepted);
  bool selected(Connection& c, Nanos t, DropReason* reason, std::string* detail);
  void rejected(Connection& c, const std::string& reason);
  void deliver(Connection& c, Nanos t, const Value& delivered);
  void apply_delivery_effects(Connection& c, Nanos t);
  void enqueue(Connection& c, const Value& v, uint64_t answered = TransportSink::kAnswersAll);
  void drain(Connection& c);
  void post_drain(Connection& c);  // one drain task per message, posted now
  void process(Connection& c, const Value& msg);
  void drop(Connection& c, DropReason reason, std::string_view detail = {});
  // Says that `where` (a connection, a mediated input) started losing messages for `reason`
  // in bulk (RunOptions::report_bulk_drops).
  void report_bulk(const std::string& where, DropReason reason);
  // Counts and reports a failing callback; quarantines after too many in a row.
  void monitor_failed(Connection& c, const LuaCall& call, const char* callback,
                      bool may_quarantine = true);
  // Takes c out of service; calls its destroy() when `destroy` (the monitor was created).
  void quarantine(Connection& c, const std::string& why, bool destroy = true);
  // Counts, traces and reports an exception that escaped plugin code.
  void plugin_failed(PluginGuard& who, const char* callback, const std::string& what);
  // The next trig of c; `restart`: the interval was (re)set now, so trig 1 is one interval on.
  void schedule_trig(Connection& c, bool restart);
  void schedule_tick(ModuleSlot& m, Nanos origin, Nanos period, uint64_t k);
  void publish_from(ModuleSlot& m, std::string_view port, Value&& v);
  // Loads c's monitor script (whose bytes must match the model's digest) and runs its create;
  // false with *error on bad input (a script that does not load, another constraint).
  bool load_monitor(Connection& c, std::string* error);
  // Runs every loaded monitor's create; false with *error when one sets another constraint.
  bool create_monitors(std::string* error);
  // How errors about the model's content start: options_.app_file, else "app NAME".
  std::string model_name() const;
  // A monitor's file as the user finds it: under the app directory.
  std::string monitor_path(const model::Connection& mc) const;
  // The lifetime app.json declares for `event` (none: until unset, also for unknown names).
  std::optional<Nanos> declared_lifetime(std::string_view event) const;
  // The mediator's memory (mediator_memory.cc): read at create (false with *error on a file
  // that does not fit), applied at start, written after each delivery and at shutdown.
  bool load_memory(std::string* error);
  void restore_memory();
  void save_memory();
  uint64_t memory_fingerprint() const;
  Connection* memory_owner(const std::string& port, const std::string& name);

  model::App app_;
  std::string app_dir_;  // where the monitors are, as create() was given it
  std::map<std::string, std::optional<Nanos>, std::less<>> lifetimes_;  // app.json's events
  std::string scenario_;
  RunOptions options_;
  std::unique_ptr<Executor> executor_;
  Trace trace_;
  std::unique_ptr<Environment> environment_;
  std::unique_ptr<EnvironmentSlot> environment_slot_;
  std::vector<std::unique_ptr<ModuleSlot>> modules_;
  std::vector<std::unique_ptr<InPort>> in_ports_;
  std::vector<std::unique_ptr<OutPort>> out_ports_;
  std::vector<std::unique_ptr<Connection>> connections_;
  std::map<std::string, InPort*, std::less<>> inputs_by_name_;
  std::map<std::string, OutPort*, std::less<>> outputs_by_name_;
  std::map<std::string, RemoteModule, std::less<>> remote_modules_;  // by name; stable addresses
  uint64_t arrivals_ = 0;  // messages from sources so far (each from_source call)
  // When the message from_source is enqueueing arrived: every connection it feeds reads this
  // instant as its stamp clock (age()), so the rules that judge it read one clock.
  // The last arrival's instant; with transport_clock_, the transport's ROS 2 time then (the
  // per-message path pays a virtual call only where /clock is read).
  Nanos arrival_at_{0};
  bool transport_clock_ = false;  // the transport has a ROS 2 time of its own (Transport::ros_time)
  uint64_t remote_sent_ = 0;      // deliveries into modules hosted elsewhere so far
  Nanos longest_lifetime_{0};     // of app.json's events: how long delivery times matter
  ModuleSet host_, mediate_;
  std::unique_ptr<TransportLink> link_;
  std::shared_ptr<Transport> transport_;  // closed by shutdown() or the destructor
  std::string transport_name_;            // transport_->name(), named by busy_ while it closes
  bool loops_back_ = false;               // transport_->loops_back()
  std::function<void(const std::string&)> reporter_;
  std::string stop_reason_;
  Nanos start_time_{0};
  std::set<std::string> failed_open_;    // events taken as absent after their feed's silence
  std::vector<uint64_t> status_losses_;  // each port's losses at the last port_status()
  Nanos status_at_ = -kNever;            // the instant of the last periodic status
  bool started_ = false, shut_down_ = false;
  BusyMarker busy_;
  std::unique_ptr<SavedMemory> memory_;  // read by create, applied (and dropped) by start
  uint64_t memory_fingerprint_ = 0;
  int memory_errors_ = 0;  // writes of the memory that failed (the first is reported)
};

}  // namespace arbc
