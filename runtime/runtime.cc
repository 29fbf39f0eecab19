// A Runtime's life cycle: start, advance, shutdown; the contexts modules and the environment
// see. Building one from the core model is runtime_create.cc.
#include <algorithm>

#include "core/time_format.h"
#include "runtime/runtime_internal.h"

namespace arbc {

uint64_t stable_hash(std::string_view s) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::mt19937_64 seeded_generator(uint64_t seed, std::string_view who) {
  std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32),
                    static_cast<uint32_t>(stable_hash(who)),
                    static_cast<uint32_t>(stable_hash(who) >> 32)};
  return std::mt19937_64(seq);
}

// --- contexts ---------------------------------------------------------------------------

// The module API's delays are seconds (runtime/module.h): to the nearest nanosecond
// (core/instant.h), so that a delay of 0.1 after 0.2 s runs at 0.3 s exactly.
static Nanos delay_of(double seconds) { return nanos_from_seconds(std::max(0.0, seconds)); }

TimerId Runtime::ModuleSlot::schedule(double delay, std::function<void()> fn) {
  return runtime->executor_->post(later(runtime->now(), delay_of(delay)),
                                  [this, fn = std::move(fn)] { guarded("timer", fn); });
}

void Runtime::ModuleSlot::log(std::string_view message) {
  runtime->trace_.log(runtime->now(), name, message);
  runtime->report(name + ": " + std::string(message));
}

TimerId Runtime::EnvironmentSlot::schedule(double delay, std::function<void()> fn) {
  return runtime->executor_->post(later(runtime->now(), delay_of(delay)),
                                  [this, fn = std::move(fn)] { guarded("timer", fn); });
}

void Runtime::EnvironmentSlot::request_stop(std::string reason) {
  if (runtime->stop_reason_.empty()) runtime->stop_reason_ = reason.empty() ? "stop" : reason;
  runtime->trace_.log(runtime->now(), "environment", "stop: " + runtime->stop_reason_);
  runtime->executor_->stop();
}

void Runtime::request_stop(const std::string& reason) {
  if (!stop_reason_.empty()) return;
  stop_reason_ = reason;
  trace_.log(now(), "runtime", "stop: " + reason);
  executor_->stop();
}

void Runtime::EnvironmentSlot::log(std::string_view message) {
  runtime->trace_.log(runtime->now(), "environment", message);
  runtime->report("environment: " + std::string(message));
}

std::optional<Nanos> Runtime::declared_lifetime(std::string_view event) const {
  auto it = lifetimes_.find(event);
  return it == lifetimes_.end() ? std::nullopt : it->second;
}

Runtime::~Runtime() {
  if (started_ && !shut_down_) shutdown();
  if (transport_) transport_->close();  // no transport thread may reach this runtime any more
}

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

std::string Runtime::run_time_text(Nanos t) const {
  // The run's end is not known yet, only the duration asked for.
  return TimeFormat::for_run(options_.duration).text(seconds_of(t));
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
  started_ = true;                        // from here on setTrigInterval schedules at once
  transport_->start(options_.interrupt);  // may wait for peers: the run's time starts after
  start_time_ = now();
  if (options_.on_start) options_.on_start(start_time_);
  restore_memory();  // after the checks start: they see the restored entries as set now
  if (options_.unknown_until_fed) collect_unknown_events();
  collect_feedback_events();
  if (options_.report_silent_lapses) watch_lapses(std::chrono::milliseconds(100));
  if (options_.on_status || (transport_ && transport_->carries_status()))
    post_status(now() + options_.status_period);
  if (environment_) {
    environment_slot_ = std::make_unique<EnvironmentSlot>();
    environment_slot_->runtime = this;
    environment_slot_->name = "environment";
    environment_slot_->kind = "environment";
    environment_slot_->random = seeded_generator(options_.seed, "environment");
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
    if (c.trig_interval == Nanos(0) && c.model->trig_interval &&
        *c.model->trig_interval > Nanos(0)) {
      c.trig_interval = *c.model->trig_interval;
    }
    if (c.trig_interval > Nanos(0) && c.has_trig && c.trig_task == 0) schedule_trig(c, true);
  }
  for (auto& m : modules_) m->guarded("start", [&] { m->module->start(); });
  for (auto& m : modules_) {
    double period = 0;
    m->guarded("tick_period", [&] { period = m->module->tick_period(); });
    // At least a nanosecond: a period that rounds to none would tick at one instant forever.
    if (period > 0) schedule_tick(*m, now(), std::max(Nanos(1), delay_of(period)), 1);
  }
}

// Tick k runs at origin + k * period (no drift from adding the period up; kNever past 64 bits).
void Runtime::schedule_tick(ModuleSlot& m, Nanos origin, Nanos period, uint64_t k) {
  auto n = static_cast<int64_t>(k);
  Nanos at = period.count() > (kNever - origin).count() / n ? kNever : origin + n * period;
  m.tick_task = executor_->post(at, [this, &m, origin, period, k] {
    m.guarded("tick", [&] { m.module->tick(); });  // a failing tick still ticks again
    schedule_tick(m, origin, period, k + 1);
  });
}

void Runtime::advance(Nanos until) { executor_->run(until); }

void Runtime::run() {
  start();
  // The run's length in the runtime's nanoseconds, at most kLongestDuration (core/instant.h).
  if (stop_reason_.empty())
    advance(std::min(nanos_from_seconds(options_.duration), kLongestDuration));
  if (options_.interrupt && options_.interrupt->load() && stop_reason_.empty()) {
    stop_reason_ = "interrupted";
    trace_.log(now(), "runtime", "stop: interrupted");
  }
  shutdown();
}

std::string Runtime::describe(const BusyMarker::Snapshot& b) {
  if (b.kind.empty()) return "";
  std::string who = b.kind == "monitor"     ? "the monitor of connection '" + b.name + "'"
                    : b.kind == "module"    ? "module '" + b.name + "'"
                    : b.kind == "transport" ? "the transport '" + b.name + "'"
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
  {
    // Marked busy: closing DDS entities takes a while (and longer sanitized); the interrupt's
    // watchdog gives it more time than a stuck callback, and names it if it still hangs.
    transport_name_ = transport_->name();
    BusyScope busy(busy_, "transport", transport_name_, "close");
    transport_->close();  // nothing arrives from other processes after the modules stopped
  }
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
  Nanos end = now();
  for (auto& cp : connections_) {
    if (!cp->queue.empty()) trace_.pending(end, cp->name, cp->queue.size());
  }
  for (auto& in : in_ports_) in->container.present(end);
  if (options_.on_status && status_at_ != end) options_.on_status(end, port_status());
  if (options_.on_finish) options_.on_finish(end, trace_);
  trace_.close();
}

}  // namespace arbc
