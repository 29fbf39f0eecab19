// Building a Runtime from the core model: the environment, the hosted modules and every port,
// the connections mediated here with their monitors, the trace and the transport.
#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "core/effective_guard.h"
#include "core/join.h"
#include "core/monitor_digests.h"
#include "runtime/runtime_internal.h"

namespace arbc {

namespace {

bool read_file(const std::string& path, std::string* text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  *text = buffer.str();
  return true;
}

// Runs a plugin's factory; returns why it failed (an exception, or no object), else "".
template <class T, class Factory>
std::string construct(const Factory& factory, std::unique_ptr<T>* out) {
  try {
    *out = factory();
  } catch (const std::exception& e) {
    return std::string("its constructor threw: ") + e.what();
  } catch (...) {
    return "its constructor threw an exception that is not a std::exception";
  }
  return *out ? "" : "its factory returned no object";
}

// A Lua error at load names a generated monitor relative to the app directory
// ("monitors/take.lua:3: ..."), as run-time errors do; said before the run, the path from here
// lets the user open it. A hand-written script's line is already the user's file.
std::string from_here(const std::string& lua_error, const std::string& monitor,
                      const std::string& path) {
  if (lua_error.rfind(monitor + ":", 0) == 0) return path + lua_error.substr(monitor.size());
  return lua_error;
}

// A monitor asked for another constraint at load: the Lua error (file and line) when the
// script let it through, else the file alone (the script caught the error itself).
std::string conflict_error(const Runtime::Connection& c, const std::string& lua_error,
                           const std::string& path) {
  if (lua_error.find(c.constraint_conflict) != std::string::npos)
    return from_here(lua_error, c.model->monitor, path);
  return path + ": setConstraint: " + c.constraint_conflict;
}

// The names, or "none".
std::string names_or_none(const std::vector<std::string>& items) {
  return items.empty() ? "none" : join(items);
}

std::unique_ptr<Executor> make_executor(const RunOptions& options) {
  if (options.realtime) return std::make_unique<RealtimeExecutor>(options.time_scale);
  return std::make_unique<SimulatedExecutor>();
}

}  // namespace

Runtime::Runtime() = default;

std::unique_ptr<Runtime> Runtime::create(const model::App& app, const std::string& app_dir,
                                         const RunOptions& options, std::string* error,
                                         Registry& registry) {
  std::unique_ptr<Runtime> rt(new Runtime());
  rt->app_ = app;
  rt->app_dir_ = app_dir;
  rt->options_ = options;
  if (!rt->options_.limits.interrupt) rt->options_.limits.interrupt = options.interrupt;
  rt->host_ = options.host;
  rt->mediate_ = options.mediate ? *options.mediate : options.host;
  for (const model::Event& e : app.events) {
    rt->lifetimes_.emplace(e.name, e.lifetime);
    if (e.lifetime) rt->longest_lifetime_ = std::max(rt->longest_lifetime_, *e.lifetime);
  }
  rt->executor_ = make_executor(options);
  rt->executor_->set_interrupt(options.interrupt);
  if (!rt->create_environment(registry, error)) return nullptr;
  if (!rt->create_modules(registry, error)) return nullptr;
  if (!rt->create_connections(error)) return nullptr;
  if (!rt->load_memory(error)) return nullptr;
  if (!rt->open_trace(error)) return nullptr;
  if (!rt->create_monitors(error)) return nullptr;
  if (!rt->open_transport(error)) return nullptr;
  return rt;
}

std::string Runtime::model_name() const {
  if (!options_.app_file.empty()) return options_.app_file;
  return app_.name.empty() ? "the app" : "app " + app_.name;
}

std::string Runtime::monitor_path(const model::Connection& mc) const {
  return app_dir_ + "/" + mc.monitor;
}

// The environment is the one registered under the app's name, else the only one registered;
// a process that hosts no module has none (the world belongs with the modules it drives).
bool Runtime::create_environment(const Registry& registry, std::string* error) {
  bool hosts_any = false;
  for (const model::Module& m : app_.modules) hosts_any |= host_.contains(m.name);
  std::vector<std::string> env_names = registry.environment_names();
  const EnvironmentFactory* factory = registry.find_environment(app_.name);
  if (!factory && env_names.size() == 1) factory = registry.find_environment(env_names[0]);
  if (factory && hosts_any) {
    std::string why = construct(*factory, &environment_);
    if (!why.empty()) {
      *error = "the environment could not be created: " + why;
      return false;
    }
  }
  // A scenario chooses what the environment does; with none here, a chosen one would change
  // nothing, and a run that ignored it would pass for the scenario it names. A process that
  // hosts no module takes the same command line as its peers, so it lets it pass.
  if (!environment_ && hosts_any && !options_.scenario.empty()) {
    *error = "--scenario '" + options_.scenario + "': this run has no environment to play it (" +
             (env_names.empty() ? std::string("no plugin registers one")
                                : "none registered for app " + app_.name +
                                      "; registered: " + names_or_none(env_names)) +
             "); load the plugin that simulates the world with --plugin, or leave --scenario out";
    return false;
  }
  std::vector<std::string> scenarios;
  if (environment_) scenarios = environment_->scenarios();
  scenario_ = options_.scenario;
  if (scenario_.empty()) scenario_ = scenarios.empty() ? "default" : scenarios.front();
  if (!scenarios.empty() &&
      std::find(scenarios.begin(), scenarios.end(), scenario_) == scenarios.end()) {
    *error =
        "unknown scenario '" + scenario_ + "'; the environment knows: " + names_or_none(scenarios);
    return false;
  }
  return true;
}

// Every module's ports exist (a mediated connection may lead to a module hosted elsewhere);
// only hosted modules get an instance from the registry.
bool Runtime::create_modules(const Registry& registry, std::string* error) {
  for (const model::Module& m : app_.modules) {
    ModuleSlot* slot = nullptr;
    if (host_.contains(m.name)) {
      const ModuleFactory* factory = registry.find_module(m.name);
      if (!factory) {
        *error = "module '" + m.name +
                 "' is not registered; load the plugin that provides it with --plugin LIB "
                 "(registered modules: " +
                 names_or_none(registry.module_names()) + ")";
        return false;
      }
      if (!create_module_slot(m, *factory, error)) return false;
      slot = modules_.back().get();
    }
    create_ports(m, slot);
  }
  return true;
}

bool Runtime::create_module_slot(const model::Module& m, const ModuleFactory& factory,
                                 std::string* error) {
  auto slot = std::make_unique<ModuleSlot>();
  slot->runtime = this;
  slot->name = m.name;
  std::string why = construct(factory, &slot->module);
  if (!why.empty()) {
    *error = "module '" + m.name + "' could not be created: " + why;
    return false;
  }
  slot->random = seeded_generator(options_.seed, m.name);
  slot->module->attach(slot.get());
  modules_.push_back(std::move(slot));
  return true;
}

// The ports of module m; `slot` is its instance, null when another process hosts it.
void Runtime::create_ports(const model::Module& m, ModuleSlot* slot) {
  RemoteModule* remote = nullptr;
  if (!slot) {
    remote = &remote_modules_[m.name];
    remote->name = m.name;
  }
  for (const model::Port& p : m.ports) {
    std::string qualified = m.name + "." + p.name;
    if (p.direction == model::Direction::In) {
      auto in = std::make_unique<InPort>();
      in->index = static_cast<int>(in_ports_.size());
      in->qualified = qualified;
      in->port = p.name;
      in->module = slot ? slot->module.get() : nullptr;
      in->slot = slot;
      in->type = p.type;
      in->mediated = mediate_.contains(m.name);
      in->remote = remote;
      in->stats.port = qualified;
      InPort* raw = in.get();
      in->container.on_expiry(
          [this, raw](int event, int owner, Nanos expiry) { lapsed(*raw, event, owner, expiry); });
      inputs_by_name_.emplace(qualified, raw);
      in_ports_.push_back(std::move(in));
    } else {
      auto out = std::make_unique<OutPort>();
      out->index = static_cast<int>(out_ports_.size());
      out->qualified = qualified;
      out->port = p.name;
      out->type = p.type;
      out->hosted = slot != nullptr;
      out->remote = remote;
      if (slot) slot->outputs.push_back(out.get());
      outputs_by_name_.emplace(qualified, out.get());
      out_ports_.push_back(std::move(out));
    }
  }
}

// The connections into the modules mediated here, with unique display names (a rule name may
// repeat across ports). Event containers name owners by index into connections_.
bool Runtime::create_connections(std::string* error) {
  std::map<std::string, int> name_count;
  for (const model::Connection& c : app_.connections) ++name_count[c.name];
  std::map<std::string, std::vector<const model::Connection*>, std::less<>> into;
  for (const model::Connection& c : app_.connections) into[c.destination].push_back(&c);
  for (size_t i = 0; i < app_.connections.size(); ++i) {
    const model::Connection& mc = app_.connections[i];
    auto dst = inputs_by_name_.find(mc.destination);
    if (dst != inputs_by_name_.end() && !dst->second->mediated) continue;
    std::string name = name_count[mc.name] > 1 ? mc.destination + "/" + mc.name : mc.name;
    if (!create_connection(i, name, into[mc.destination], error)) return false;
  }
  return true;
}

// A feed whose source is an arbitrated input port carries a delivery event
// (docs/design.md#delivery-events): it runs on what that port delivers, in the same task as the
// delivery, so the port must be mediated here too; otherwise its deliveries happen in another
// process and the events would never be set here, so rules reading `not EVENT` would be
// selected while the proof took them to be blocked.
bool Runtime::attach_delivery_feed(Connection& c, const std::string& where, std::string* error) {
  const model::Connection& mc = *c.model;
  auto from = inputs_by_name_.find(mc.source);
  if (!c.is_feed || from == inputs_by_name_.end()) {
    *error = where + ": source " + mc.source + " is not an output port of a module in the app";
    return false;
  }
  if (!from->second->mediated) {
    *error = where + ": the delivery events it carries (" + join(mc.sets) + ") come from what " +
             mc.source + " delivers, which another process mediates; mediate " + mc.source +
             " and " + mc.destination + " in one process (--mediate)";
    return false;
  }
  c.delivered_from = from->second;
  return true;
}

bool Runtime::create_connection(size_t i, const std::string& display_name,
                                std::span<const model::Connection* const> into,
                                std::string* error) {
  const model::Connection& mc = app_.connections[i];
  auto c = std::make_unique<Connection>();
  c->runtime = this;
  c->index = static_cast<int>(connections_.size());
  c->model = &mc;
  c->name = display_name;
  auto src = outputs_by_name_.find(mc.source);
  auto dst = inputs_by_name_.find(mc.destination);
  // What follows is about the model's content: it names where the model came from.
  std::string where = model_name() + ": connection '" + mc.name + "'";
  c->is_feed = mc.kind == model::ConnectionKind::Feed;
  if (src != outputs_by_name_.end()) {
    c->source = src->second;
  } else if (!attach_delivery_feed(*c, where, error)) {
    return false;
  }
  if (dst == inputs_by_name_.end()) {
    *error =
        where + ": destination " + mc.destination + " is not an input port of a module in the app";
    return false;
  }
  c->destination = dst->second;
  c->throttle = mc.throttle;
  c->list_bound = mc.list_bound;
  // A rule is selected on its effective guard without the activity event, which equals its
  // constraint whenever its monitor does what app.json says (core/effective_guard.h): so a
  // monitor that does otherwise cannot deliver in a state the proof took to be impossible.
  Constraint selection =
      mc.kind == model::ConnectionKind::Rule ? model::decision_guard(into, mc) : mc.constraint;
  c->constraint = CompiledConstraint::compile(selection, c->destination->container.index());
  c->constraint_text = mc.constraint.to_string();
  c->stats.name = c->name;
  c->stats.source = mc.source;
  c->stats.destination = mc.destination;
  c->stats.model_index = i;
  if (!mc.monitor.empty() && !load_monitor(*c, error)) return false;
  if (!c->has_update && !c->is_feed && !same_type(*c->source->type, *c->destination->type)) {
    *error = where + ": " + mc.source + " carries " + c->source->type->to_string() + " but " +
             mc.destination + " takes " + c->destination->type->to_string() +
             ", and no monitor update converts it";
    return false;
  }
  if (c->source) c->source->connections.push_back(c.get());
  if (c->delivered_from) c->delivered_from->delivery_feeds.push_back(c.get());
  if (c->is_feed) c->destination->feeds.push_back(c.get());
  connections_.push_back(std::move(c));
  return true;
}

bool Runtime::open_trace(std::string* error) {
  trace_.record_to(options_.trace_records);
  if (options_.trace_watch) trace_.watch_with(options_.trace_watch);
  if (options_.trace_path.empty()) return true;
  return trace_.open(options_.trace_path, error);
}

// What an output reaches in this process: its connections (not the generated feeds) and the
// events their monitors set (a rule's `by priority` hold is the runtime's, not the source's).
static void describe_reach(const Runtime::OutPort& out, TransportPort& tp) {
  std::set<std::string> events;
  for (const Runtime::Connection* c : out.connections) {
    if (!c->is_feed) tp.connections.push_back(c->name + " into " + c->model->destination);
    for (const std::string& e : c->model->sets)
      if (!c->model->set_on_delivery(e)) events.insert(e);
  }
  tp.events.assign(events.begin(), events.end());
}

// Tells the transport where every port's module runs; in-process unless the options name one.
bool Runtime::open_transport(std::string* error) {
  transport_ = options_.transport ? options_.transport : make_inproc_transport();
  loops_back_ = transport_->loops_back();
  TransportPlan plan;
  plan.app = app_.name;
  for (const model::Module& m : app_.modules) {
    for (const model::Port& p : m.ports) {
      std::string qualified = m.name + "." + p.name;
      TransportPort tp{0, m.name, p.name, qualified, p.type, host_.contains(m.name), false, {}, {}};
      if (p.direction == model::Direction::In) {
        const InPort& in = *inputs_by_name_.at(qualified);
        tp.index = in.index;
        tp.mediated = in.mediated;
        plan.inputs.push_back(tp);
      } else {
        const OutPort& out = *outputs_by_name_.at(qualified);
        tp.index = out.index;
        tp.mediated = !out.connections.empty();
        describe_reach(out, tp);
        plan.outputs.push_back(tp);
      }
    }
  }
  link_ = std::make_unique<TransportLink>(this);
  if (!transport_->open(plan, link_.get(), error)) return false;
  transport_clock_ = transport_->ros_time().has_value();
  return true;
}

// Each monitor's create runs at load, so that a setConstraint that would replace the
// constraint app.json records is bad input before anything runs. A create that fails or
// returns false quarantines its connection when the run starts (start()).
bool Runtime::create_monitors(std::string* error) {
  for (auto& cp : connections_) {
    Connection& c = *cp;
    if (!c.monitor) continue;
    bool created = false;
    LuaCall call;
    {
      BusyScope busy(busy_, "monitor", c.name, "create");
      call = c.monitor->create({c.model->source, c.model->destination, c.name}, &created);
    }
    if (!c.constraint_conflict.empty()) {
      *error = conflict_error(c, call.error, monitor_path(*c.model));
      return false;
    }
    if (!call.ok()) {
      c.create_failure = call.error;
    } else {
      c.create_refused = !created;
    }
  }
  return true;
}

bool Runtime::load_monitor(Connection& c, std::string* error) {
  const model::Connection& mc = *c.model;
  std::string where = "connection '" + mc.name + "'";
  std::string path = monitor_path(mc);
  std::string script;
  if (!read_file(path, &script)) {
    *error =
        where + ": cannot read its monitor script " + path + " (rebuild the app with `arbc build`)";
    return false;
  }
  // What runs must be what was built (and proved): the bytes, not only the file name.
  if (!model::monitor_matches_digest(mc, path, script, error)) return false;
  std::string load_error;
  c.monitor = LuaMonitor::load(script, mc.monitor, options_.limits, &c, &load_error);
  if (!c.constraint_conflict.empty()) {  // setConstraint at the script's top level
    *error = conflict_error(c, load_error, path);
    return false;
  }
  if (!c.monitor) {
    *error =
        where + ": its monitor script failed to load: " + from_here(load_error, mc.monitor, path);
    // `arbc import yarp` keeps each YARP monitor as the rule's `script`, which runs on YARP's
    // Lua API (require("yarp"), PortMonitor.*), not on this runtime: say what to do instead of
    // leaving the user with "attempt to call a nil value (global 'require')".
    if (script.find("PortMonitor.") != std::string::npos)
      *error +=
          " (the script is a YARP port monitor, written for YARP's Lua API; arbc's "
          "runtime cannot run it: replace the rule's `script` with spec statements, see "
          "docs/yarp.md#moving-to-a-spec)";
    return false;
  }
  c.has_accept = c.monitor->defines("accept");
  c.has_update = c.monitor->defines("update");
  c.has_trig = c.monitor->defines("trig");
  return true;
}

}  // namespace arbc
