// The pieces of a Runtime, shared by runtime.cc (building and life cycle), message_path.cc
// and runtime_stats.cc. Not part of the public API.
#pragma once

#include <limits>
#include <random>

#include "runtime/runtime.h"

namespace arbc {

// An input port of a module instance, with its event container.
struct Runtime::InPort {
  std::string qualified;  // "Module.port"
  std::string port;
  Module* module = nullptr;
  ModuleSlot* slot = nullptr;
  TypePtr type;
  EventContainer container;
};

// An output port and the connections leaving it, in model order.
struct Runtime::OutPort {
  std::string qualified;
  std::string port;
  TypePtr type;
  std::vector<Connection*> connections;
  std::set<std::string> reported;  // publish errors already reported
};

struct Runtime::Connection : MonitorHost {
  Runtime* runtime = nullptr;
  int index = 0;  // owner id in event containers
  std::string name;
  const model::Connection* model = nullptr;
  OutPort* source = nullptr;
  InPort* destination = nullptr;
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

  std::deque<Value> queue;
  bool drain_posted = false;
  std::optional<double> throttle;
  double last_delivery = -std::numeric_limits<double>::infinity();
  double trig_interval = 0;
  Executor::TaskId trig_task = 0;

  int consecutive_errors = 0;
  bool quarantined = false;
  std::set<std::string> reported_errors;
  ConnectionStats stats;

  // MonitorHost: PortMonitor calls from this connection's script.
  double now() override;
  void set_event(std::string_view event, std::optional<double> lifetime) override;
  void unset_event(std::string_view event) override;
  bool has_event(std::string_view event) override;
  std::string set_constraint(std::string_view text) override;
  std::string get_constraint() override { return constraint_text; }
  void set_trig_interval(double seconds) override;
  void print(const std::string& line) override;
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
  std::map<std::string, OutPort*, std::less<>> outputs;
  std::mt19937_64 random;
  Executor::TaskId tick_task = 0;
  std::set<std::string> reported;  // publish errors already reported

  double now() const override { return runtime->now(); }
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

  double now() const override { return runtime->now(); }
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
