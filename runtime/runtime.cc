// Building a Runtime from the core model, and its life cycle.
#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/join.h"
#include "core/monitor_digests.h"
#include "runtime/runtime_internal.h"

namespace arbc {

namespace {

// FNV-1a: a stable hash (std::hash may differ between builds) for per-module seeds.
uint64_t stable_hash(std::string_view s) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::mt19937_64 seeded(uint64_t seed, std::string_view who) {
  std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32),
                    static_cast<uint32_t>(stable_hash(who)),
                    static_cast<uint32_t>(stable_hash(who) >> 32)};
  return std::mt19937_64(seq);
}

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

// A monitor asked for another constraint at load: the Lua error (file and line) when the
// script let it through, else the file alone (the script caught the error itself).
std::string conflict_error(const Runtime::Connection& c, const std::string& lua_error) {
  if (lua_error.find(c.constraint_conflict) != std::string::npos) return lua_error;
  return c.model->monitor + ": setConstraint: " + c.constraint_conflict;
}

// The names, or "none".
std::string names_or_none(const std::vector<std::string>& items) {
  return items.empty() ? "none" : join(items);
}

}  // namespace

// --- contexts ---------------------------------------------------------------------------

TimerId Runtime::ModuleSlot::schedule(double delay, std::function<void()> fn) {
  return runtime->executor_->post(runtime->now() + std::max(0.0, delay),
                                  [this, fn = std::move(fn)] { guarded("timer", fn); });
}

void Runtime::ModuleSlot::log(std::string_view message) {
  runtime->trace_.log(runtime->now(), name, message);
  runtime->report(name + ": " + std::string(message));
}

TimerId Runtime::EnvironmentSlot::schedule(double delay, std::function<void()> fn) {
  return runtime->executor_->post(runtime->now() + std::max(0.0, delay),
                                  [this, fn = std::move(fn)] { guarded("timer", fn); });
}

void Runtime::EnvironmentSlot::request_stop(std::string reason) {
  if (runtime->stop_reason_.empty()) runtime->stop_reason_ = reason.empty() ? "stop" : reason;
  runtime->trace_.log(runtime->now(), "environment", "stop: " + runtime->stop_reason_);
  runtime->executor_->stop();
}

void Runtime::EnvironmentSlot::log(std::string_view message) {
  runtime->trace_.log(runtime->now(), "environment", message);
  runtime->report("environment: " + std::string(message));
}

// --- building ---------------------------------------------------------------------------

std::unique_ptr<Runtime> Runtime::create(const model::App& app, const std::string& app_dir,
                                         const RunOptions& options, std::string* error,
                                         Registry& registry) {
  std::unique_ptr<Runtime> rt(new Runtime());
  rt->app_ = app;
  rt->options_ = options;
  if (!rt->options_.limits.interrupt) rt->options_.limits.interrupt = options.interrupt;
  for (const model::Event& e : app.events) rt->lifetimes_.emplace(e.name, e.lifetime);
  if (options.realtime) {
    rt->executor_ = std::make_unique<RealtimeExecutor>();
  } else {
    rt->executor_ = std::make_unique<SimulatedExecutor>();
  }
  rt->executor_->set_interrupt(options.interrupt);

  // The environment: the one named after the app, else the only one registered.
  std::vector<std::string> env_names = registry.environment_names();
  const EnvironmentFactory* env_factory = registry.find_environment(app.name);
  if (!env_factory && env_names.size() == 1) env_factory = registry.find_environment(env_names[0]);
  if (env_factory) {
    std::string why = construct(*env_factory, &rt->environment_);
    if (!why.empty()) {
      *error = "the environment could not be created: " + why;
      return nullptr;
    }
  }
  std::vector<std::string> scenarios;
  if (rt->environment_) scenarios = rt->environment_->scenarios();
  rt->scenario_ = options.scenario;
  if (rt->scenario_.empty()) rt->scenario_ = scenarios.empty() ? "default" : scenarios.front();
  if (!scenarios.empty() &&
      std::find(scenarios.begin(), scenarios.end(), rt->scenario_) == scenarios.end()) {
    *error = "unknown scenario '" + rt->scenario_ +
             "'; the environment knows: " + names_or_none(scenarios);
    return nullptr;
  }

  // Modules and their ports.
  Runtime* self = rt.get();
  std::map<std::string, InPort*, std::less<>> inputs;
  std::map<std::string, OutPort*, std::less<>> outputs;
  for (const model::Module& m : app.modules) {
    const ModuleFactory* factory = registry.find_module(m.name);
    if (!factory) {
      *error = "module '" + m.name +
               "' is not registered; load the plugin that provides it with --plugin LIB "
               "(registered modules: " +
               names_or_none(registry.module_names()) + ")";
      return nullptr;
    }
    auto slot = std::make_unique<ModuleSlot>();
    slot->runtime = self;
    slot->name = m.name;
    std::string why = construct(*factory, &slot->module);
    if (!why.empty()) {
      *error = "module '" + m.name + "' could not be created: " + why;
      return nullptr;
    }
    slot->random = seeded(options.seed, m.name);
    slot->module->attach(slot.get());
    for (const model::Port& p : m.ports) {
      std::string qualified = m.name + "." + p.name;
      if (p.direction == model::Direction::In) {
        auto in = std::make_unique<InPort>();
        in->qualified = qualified;
        in->port = p.name;
        in->module = slot->module.get();
        in->slot = slot.get();
        in->type = p.type;
        InPort* raw = in.get();
        in->container.on_expiry([self, raw](int event, int owner, double expiry) {
          self->trace_.event(expiry, raw->qualified, "expire", raw->container.index().name(event),
                             self->connections_[static_cast<size_t>(owner)]->name, expiry);
        });
        inputs.emplace(qualified, raw);
        rt->in_ports_.push_back(std::move(in));
      } else {
        auto out = std::make_unique<OutPort>();
        out->qualified = qualified;
        out->port = p.name;
        out->type = p.type;
        outputs.emplace(qualified, out.get());
        slot->outputs.emplace(p.name, out.get());
        rt->out_ports_.push_back(std::move(out));
      }
    }
    rt->modules_.push_back(std::move(slot));
  }

  // Connections, with unique display names (a rule name may repeat across ports).
  std::map<std::string, int> name_count;
  for (const model::Connection& c : app.connections) ++name_count[c.name];
  for (size_t i = 0; i < rt->app_.connections.size(); ++i) {
    const model::Connection& mc = rt->app_.connections[i];
    auto c = std::make_unique<Connection>();
    c->runtime = self;
    c->index = static_cast<int>(i);
    c->model = &mc;
    c->name = name_count[mc.name] > 1 ? mc.destination + "/" + mc.name : mc.name;
    auto src = outputs.find(mc.source);
    auto dst = inputs.find(mc.destination);
    std::string where = "connection '" + mc.name + "'";
    if (src == outputs.end()) {
      *error = where + ": source " + mc.source + " is not an output port of a module in the app";
      return nullptr;
    }
    if (dst == inputs.end()) {
      *error = where + ": destination " + mc.destination +
               " is not an input port of a module in the app";
      return nullptr;
    }
    c->source = src->second;
    c->destination = dst->second;
    c->is_feed = mc.kind == model::ConnectionKind::Feed;
    c->throttle = mc.throttle;
    c->constraint = CompiledConstraint::compile(mc.constraint, c->destination->container.index());
    c->constraint_text = mc.constraint.to_string();
    c->stats.name = c->name;
    c->stats.source = mc.source;
    c->stats.destination = mc.destination;
    if (!mc.monitor.empty() && !rt->load_monitor(*c, app_dir, error)) return nullptr;
    if (!c->has_update && !c->is_feed && !same_type(*c->source->type, *c->destination->type)) {
      *error = where + ": " + mc.source + " carries " + c->source->type->to_string() + " but " +
               mc.destination + " takes " + c->destination->type->to_string() +
               ", and no monitor update converts it";
      return nullptr;
    }
    c->source->connections.push_back(c.get());
    rt->connections_.push_back(std::move(c));
  }

  rt->trace_.record_to(options.trace_records);
  if (!options.trace_path.empty()) {
    std::string trace_error = rt->trace_.open(options.trace_path);
    if (!trace_error.empty()) {
      *error = trace_error;
      return nullptr;
    }
  }
  if (!rt->create_monitors(error)) return nullptr;
  return rt;
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
      *error = conflict_error(c, call.error);
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

bool Runtime::load_monitor(Connection& c, const std::string& app_dir, std::string* error) {
  const model::Connection& mc = *c.model;
  std::string where = "connection '" + mc.name + "'";
  std::string path = app_dir + "/" + mc.monitor;
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
    *error = conflict_error(c, load_error);
    return false;
  }
  if (!c.monitor) {
    *error = where + ": its monitor script failed to load: " + load_error;
    return false;
  }
  c.has_accept = c.monitor->defines("accept");
  c.has_update = c.monitor->defines("update");
  c.has_trig = c.monitor->defines("trig");
  return true;
}

std::optional<double> Runtime::declared_lifetime(std::string_view event) const {
  auto it = lifetimes_.find(event);
  return it == lifetimes_.end() ? std::nullopt : it->second;
}

Runtime::~Runtime() {
  if (started_ && !shut_down_) shutdown();
}

double Runtime::now() const { return executor_->now(); }

Module* Runtime::module(std::string_view name) {
  for (auto& m : modules_) {
    if (m->name == name) return m->module.get();
  }
  return nullptr;
}

void Runtime::plugin_failed(PluginGuard& who, const char* callback, const std::string& what) {
  ++who.errors;
  trace_.plugin_error(now(), who.name, callback, what);
  std::string line = who.name + ": " + callback + " threw: " + what;
  if (who.reported_errors.insert(line).second) {
    report(line + " (the run goes on; this error is reported once)");
  }
}

void Runtime::report(const std::string& line) {
  if (reporter_) {
    reporter_(line);
  } else {
    std::fprintf(stderr, "arbc run: %s\n", line.c_str());
  }
}

// --- life cycle -------------------------------------------------------------------------

void Runtime::start() {
  if (started_) return;
  started_ = true;  // from here on setTrigInterval schedules at once
  if (environment_) {
    environment_slot_ = std::make_unique<EnvironmentSlot>();
    environment_slot_->runtime = this;
    environment_slot_->name = "environment";
    environment_slot_->kind = "environment";
    environment_slot_->random = seeded(options_.seed, "environment");
    environment_slot_->guarded("setup", [&] { environment_->setup(*environment_slot_); });
  }
  for (auto& cp : connections_) {
    Connection& c = *cp;
    if (!c.monitor) continue;
    if (c.create_refused) {
      quarantine(c, "create returned false", false);
      continue;
    }
    if (!c.create_failure.empty()) {  // create (run at load) failed: counted, traced, out
      ++c.stats.errors;
      trace_.error(now(), c.name, c.create_failure);
      quarantine(c, "create failed: " + c.create_failure, false);
      continue;
    }
    if (c.trig_interval == 0 && c.model->trig_interval && *c.model->trig_interval > 0) {
      c.trig_interval = *c.model->trig_interval;
    }
    if (c.trig_interval > 0 && c.has_trig && c.trig_task == 0) schedule_trig(c);
  }
  for (auto& m : modules_) m->guarded("start", [&] { m->module->start(); });
  for (auto& m : modules_) {
    double period = 0;
    m->guarded("tick_period", [&] { period = m->module->tick_period(); });
    if (period > 0) schedule_tick(*m, now(), period, 1);
  }
}

// Tick k runs at origin + k * period (no drift from adding the period up).
void Runtime::schedule_tick(ModuleSlot& m, double origin, double period, uint64_t k) {
  m.tick_task =
      executor_->post(origin + static_cast<double>(k) * period, [this, &m, origin, period, k] {
        m.guarded("tick", [&] { m.module->tick(); });  // a failing tick still ticks again
        schedule_tick(m, origin, period, k + 1);
      });
}

void Runtime::advance(double until) { executor_->run(until); }

void Runtime::run() {
  start();
  if (stop_reason_.empty()) advance(options_.duration);
  if (options_.interrupt && options_.interrupt->load() && stop_reason_.empty()) {
    stop_reason_ = "interrupted";
    trace_.log(now(), "runtime", "stop: interrupted");
  }
  shutdown();
}

std::string Runtime::describe(const BusyMarker::Snapshot& b) {
  if (b.kind.empty()) return "";
  std::string who = b.kind == "monitor"  ? "the monitor of connection '" + b.name + "'"
                    : b.kind == "module" ? "module '" + b.name + "'"
                                         : "the environment";
  return who + ", in " + b.callback;
}

void Runtime::abandon_trace(const std::string& why) {
  trace_.log(now(), "runtime", "stop: " + why);
  trace_.close();
}

void Runtime::shutdown() {
  if (shut_down_) return;
  shut_down_ = true;
  for (auto& m : modules_) m->guarded("stop", [&] { m->module->stop(); });
  for (auto& cp : connections_) {
    Connection& c = *cp;
    if (c.monitor && !c.quarantined) {
      LuaCall call;
      {
        BusyScope busy(busy_, "monitor", c.name, "destroy");
        call = c.monitor->destroy();
      }
      if (!call.ok()) monitor_failed(c, call, "destroy", false);
    }
  }
  if (environment_) {
    if (environment_slot_) {
      environment_slot_->guarded("finish", [&] { environment_->finish(); });
    } else {
      environment_->finish();  // never started: setup did not run either
    }
  }
  // Let the trace show every lapse up to the end of the run, and what was left queued.
  double end = now();
  for (auto& cp : connections_) {
    if (!cp->queue.empty()) trace_.pending(end, cp->name, cp->queue.size());
  }
  for (auto& in : in_ports_) in->container.present(end);
  trace_.close();
}

}  // namespace arbc
