// The module API: what a module author (and the simulated world) codes against.
//
// A module is a C++ class with typed ports, registered by name. The runtime creates one
// instance per module of the app (the module's name in app.json is its registered name),
// calls start(), delivers messages that reach its input ports, calls tick() at the period it
// asks for, and calls stop() at the end. All callbacks of all modules run on the executor's
// thread, one at a time, so module code needs no locks. Time is in seconds: simulated time
// (starting at 0) under the simulated executor, wall time since start under --realtime.
//
//   class Speak : public arbc::Module {
//    public:
//     Speak() { in("text", "string"); }
//     void on_message(const std::string& port, const arbc::Value& v) override {
//       said_.push_back(v.as_string());
//     }
//   };
//   ARBC_REGISTER_MODULE(Speak, "Speak");
//
// An environment (the simulated world of a plugin) is registered the same way with
// ARBC_REGISTER_ENVIRONMENT; see Environment below. Plugins are shared libraries loaded with
// `arbc run --plugin LIB`; their registrars run when the library is loaded.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "core/value.h"

namespace arbc {

class Environment;

// A port a module declares: name, direction and type text in the spec syntax
// ("list<{pos: vec3, dist: float}>", see core/type.h).
struct PortDecl {
  std::string name;
  bool is_input = true;
  std::string type;
};

using TimerId = uint64_t;

// What the runtime offers a running module. Implemented by the runtime; one per module.
class ModuleContext {
 public:
  virtual ~ModuleContext() = default;
  virtual double now() const = 0;
  // Sends v on the output port `port` to every connection from it. Unknown port or a value
  // that does not conform to the port's type: the message is dropped and reported once.
  virtual void publish(std::string_view port, Value v) = 0;
  // Runs fn once, `delay` seconds from now (0: after the current callback, in order).
  virtual TimerId schedule(double delay, std::function<void()> fn) = 0;
  virtual void cancel(TimerId id) = 0;
  // Seeded from --seed and the module's name: deterministic, independent per module.
  virtual std::mt19937_64& rng() = 0;
  virtual const std::string& scenario() const = 0;
  virtual uint64_t seed() const = 0;
  virtual const std::string& module_name() const = 0;
  // The run's environment (nullptr when none was registered).
  virtual Environment* environment() = 0;
  // A line for the run's log (stderr) and the trace.
  virtual void log(std::string_view message) = 0;
};

// Who delivered a message: an input port may be fed by several connections (arbitration).
// The references are valid during the callback only.
struct Delivery {
  const std::string& port;  // this module's input port
  const Value& value;
  const std::string& connection;  // the connection's name in app.json ("take", "search", ...)
  const std::string& source;      // "Module.port" it came from
  double time = 0;
};

class Module {
 public:
  virtual ~Module() = default;

  // Declared ports, in declaration order (the loader checks them against app.json).
  const std::vector<PortDecl>& ports() const { return ports_; }

  // Called once, after every module exists and the environment is set up.
  virtual void start() {}
  // A message delivered to one of this module's input ports. The default of on_delivery
  // calls on_message; override on_delivery to see which connection delivered it.
  virtual void on_message(const std::string& port, const Value& value) {}
  virtual void on_delivery(const Delivery& d) { on_message(d.port, d.value); }
  // Period (seconds) of tick(); 0 (the default) means no periodic tick. Read after start().
  virtual double tick_period() const { return 0; }
  virtual void tick() {}
  // Called once at the end of the run (duration reached, environment finished, shutdown).
  virtual void stop() {}

  // Set by the runtime before start(); valid until after stop().
  void attach(ModuleContext* context) { context_ = context; }
  ModuleContext& context() { return *context_; }

 protected:
  // Port declarations, usually in the constructor.
  void in(std::string name, std::string type) {
    ports_.push_back({std::move(name), true, std::move(type)});
  }
  void out(std::string name, std::string type) {
    ports_.push_back({std::move(name), false, std::move(type)});
  }

  // Shorthands for context() calls.
  double now() const { return context_->now(); }
  void publish(std::string_view port, Value v) { context_->publish(port, std::move(v)); }
  TimerId schedule(double delay, std::function<void()> fn) {
    return context_->schedule(delay, std::move(fn));
  }
  std::mt19937_64& rng() { return context_->rng(); }
  // The environment as its concrete class, or nullptr.
  template <class T>
  T* environment() {
    return dynamic_cast<T*>(context_->environment());
  }

 private:
  std::vector<PortDecl> ports_;
  ModuleContext* context_ = nullptr;
};

// What the runtime offers the environment.
class EnvironmentContext {
 public:
  virtual ~EnvironmentContext() = default;
  virtual double now() const = 0;
  virtual TimerId schedule(double delay, std::function<void()> fn) = 0;
  virtual void cancel(TimerId id) = 0;
  virtual std::mt19937_64& rng() = 0;  // seeded from --seed
  virtual const std::string& scenario() const = 0;
  virtual uint64_t seed() const = 0;
  // Ends the run early (e.g. "table clean"); finish() is still called. The reason is printed.
  virtual void request_stop(std::string reason) = 0;
  // Looks up a running module instance by its app name (nullptr when absent).
  virtual Module* module(std::string_view name) = 0;
  virtual void log(std::string_view message) = 0;
};

// A world or test harness around the modules: set up before the modules start, asked for a
// verdict at the end. `arbc run` prints summary() and exits 0 only when success() is true,
// 3 otherwise. At most one environment is used per run: the one registered under the app's
// name, else the only one registered.
class Environment {
 public:
  virtual ~Environment() = default;
  // Scenarios this environment knows; empty means any name is accepted. `arbc run --scenario`
  // with an unknown name is a usage error listing these.
  virtual std::vector<std::string> scenarios() const { return {}; }
  // Called once before any module starts; ctx stays valid until after finish().
  virtual void setup(EnvironmentContext& ctx) {}
  // Called once after the last module stopped.
  virtual void finish() {}
  // Human-readable multi-line result, printed by `arbc run`.
  virtual std::string summary() const { return {}; }
  virtual bool success() const { return true; }
};

using ModuleFactory = std::function<std::unique_ptr<Module>()>;
using EnvironmentFactory = std::function<std::unique_ptr<Environment>()>;

// The process-wide registry of module and environment classes. Registering a name twice
// keeps the first and records an error that the runner reports.
class Registry {
 public:
  static Registry& global();

  bool add_module(std::string name, ModuleFactory factory);
  bool add_environment(std::string name, EnvironmentFactory factory);
  const ModuleFactory* find_module(std::string_view name) const;
  const EnvironmentFactory* find_environment(std::string_view name) const;
  std::vector<std::string> module_names() const;       // sorted
  std::vector<std::string> environment_names() const;  // sorted
  const std::vector<std::string>& errors() const { return errors_; }

 private:
  std::map<std::string, ModuleFactory, std::less<>> modules_;
  std::map<std::string, EnvironmentFactory, std::less<>> environments_;
  std::vector<std::string> errors_;
};

// Loads a plugin (a shared library whose static registrars call Registry::global()).
// False and *err when it cannot: dlopen's message, or that the library registered nothing.
bool load_plugin(const std::string& path, std::string* err);

}  // namespace arbc

#define ARBC_CONCAT_INNER_(a, b) a##b
#define ARBC_CONCAT_(a, b) ARBC_CONCAT_INNER_(a, b)

// ARBC_REGISTER_MODULE(ClassName, "Name"): at load time, registers ClassName under "Name".
#define ARBC_REGISTER_MODULE(Class, Name)                                                 \
  [[maybe_unused]] static const bool ARBC_CONCAT_(arbc_module_registered_, __COUNTER__) = \
      ::arbc::Registry::global().add_module(Name, [] { return std::make_unique<Class>(); })

// ARBC_REGISTER_ENVIRONMENT(ClassName, "app_name"): registers an environment.
#define ARBC_REGISTER_ENVIRONMENT(Class, Name)                                         \
  [[maybe_unused]] static const bool ARBC_CONCAT_(arbc_env_registered_, __COUNTER__) = \
      ::arbc::Registry::global().add_environment(Name, [] { return std::make_unique<Class>(); })
