// The message path of docs/design.md#the-message-path: queueing, accept, constraint, throttle,
// update, delivery (which sets a `by priority` rule's activity event); drops, script failures
// and quarantine; the PortMonitor calls of a connection.
#include <algorithm>
#include <string>

#include "core/instant.h"
#include "runtime/runtime_internal.h"

namespace arbc {

// --- publishing and queues ---------------------------------------------------------------

void Runtime::publish(std::string_view module, std::string_view port, Value v) {
  for (auto& m : modules_) {
    if (same_name(m->name, module)) {
      publish_from(*m, port, std::move(v));
      return;
    }
  }
  report("publish: no module named " + std::string(module));
}

void Runtime::publish_from(ModuleSlot& m, std::string_view port, Value&& v) {
  if (!executor_->on_executor_thread()) {
    // Real time: a module's own thread published; hand the message to the executor thread.
    std::string port_name(port);
    executor_->post(now(), [this, &m, port_name, v = std::move(v)]() mutable {
      publish_from(m, port_name, std::move(v));
    });
    return;
  }
  OutPort* found = m.output(port);
  if (!found) {
    std::string message = "module " + m.name + " published on '" + std::string(port) +
                          "', which is not one of its output ports in the app";
    trace_.publish_error(now(), m.name + "." + std::string(port), message);
    if (m.reported.insert(message).second) report(message);
    return;
  }
  OutPort& out = *found;
  if (!conforms(v, *out.type, nullptr)) {
    std::string why;  // built only for a value that does not conform: the check runs again
    conforms(v, *out.type, &why);
    std::string message = "module " + m.name + " published a value on " + out.qualified +
                          " that is not a " + out.type->to_string() + " (" + why + ")";
    trace_.publish_error(now(), out.qualified, message);
    if (out.reported.insert(message).second) report(message);
    // The message was meant for every connection from the port: each counts and traces it.
    for (Connection* c : out.connections) {
      ++c->stats.arrived;
      drop(*c, DropReason::BadType, why);
    }
    return;
  }
  if (trace_.enabled()) trace_.publish(now(), out.qualified, v);
  if (loops_back_) {
    from_source(out, v, TransportSink::kAnswersAll);
  } else {
    transport_->publish(out.index, v);
  }
}

// A message from `out` for the connections mediated here. One from a module hosted elsewhere
// is this process's input: traced as a `publish` line here (a hosted one was, in publish_from).
void Runtime::from_source(OutPort& out, const Value& v, uint64_t answered) {
  if (!out.hosted && trace_.enabled()) trace_.publish(now(), out.qualified, v);
  ++arrivals_;
  arrival_at_ = transport_clock_ ? *transport_->ros_time() : now();
  for (Connection* c : out.connections) enqueue(*c, v, answered);
}

void Runtime::to_module(InPort& in, const Delivery& d) {
  if (!in.slot) return;  // the transport routes only to hosted modules; defensive
  if (!in.mediated) {
    ++in.stats.arrived;
    ++in.stats.delivered;
  }
  // The message was delivered; if the module throws handling it, that is the module's fault.
  in.slot->guarded("on_delivery", [&] { in.module->on_delivery(d); });
}

// Counted where the message was going: on each connection from an output (as a publish of a
// bad value is), or on a hosted module's input mediated by another process.
void Runtime::lost(bool input, int index, DropReason reason, uint64_t count,
                   const std::string& detail) {
  if (input) {
    InPort& in = *in_ports_[static_cast<size_t>(index)];
    in.stats.arrived += count;
    in.stats.dropped[static_cast<int>(reason)] += count;
    trace_.publish_error(now(), in.qualified,
                         std::string(drop_reason_name(reason)) + ": " + detail);
    if (options_.report_bulk_drops && in.bulk.count(reason, count, now()))
      report_bulk("input " + in.qualified, reason);
    return;
  }
  OutPort& out = *out_ports_[static_cast<size_t>(index)];
  for (Connection* c : out.connections) {
    for (uint64_t k = 0; k < count; ++k) {
      ++c->stats.arrived;
      drop(*c, reason, detail);
    }
  }
}

namespace {

// The number of elements of the longest list in v, at any depth (0: none), but for a fixed list
// (T[N], type `t` when known): the proof holds each of its N elements, so it sets no bound.
size_t longest_list(const Value& v, const Type* t) {
  size_t n = 0;
  if (v.is_list()) {
    const Type* element = t && t->kind == Type::Kind::List ? t->element.get() : nullptr;
    if (!t || !t->fixed) n = v.as_list().size();
    for (const Value& e : v.as_list()) n = std::max(n, longest_list(e, element));
  } else if (v.is_record()) {
    for (const auto& [name, f] : v.as_record()) {
      const Field* field = t ? t->field(name) : nullptr;
      n = std::max(n, longest_list(f, field ? field->type.get() : nullptr));
    }
  }
  return n;
}

}  // namespace

void Runtime::enqueue(Connection& c, const Value& v, uint64_t answered) {
  ++c.stats.arrived;
  c.last_arrival = now();
  if (!c.silence_reported.empty()) c.silence_reported.clear();
  if (c.quarantined) {
    drop(c, DropReason::Quarantined);
    return;
  }
  // The proof of this rule covers lists of at most list_bound elements (app.json): a longer
  // one is not delivered under a proof that excluded it.
  if (c.list_bound > 0) {
    size_t n = longest_list(v, c.source ? c.source->type.get() : nullptr);
    if (n > static_cast<size_t>(c.list_bound)) {
      drop(c, DropReason::BadValue,
           "a list of " + std::to_string(n) + " elements; the proof covers at most " +
               std::to_string(c.list_bound) + " (arbc verify --list-bound)");
      return;
    }
  }
  if (c.queue.size() >= options_.queue_capacity) {
    drop(c, DropReason::QueueFull);
    return;
  }
  Connection::Queued& queued = c.queue.push_back();
  queued.value = v;
  queued.answered = answered;
  queued.message = arrivals_;
  queued.arrived = arrival_at_;
  if (!c.drain_posted) post_drain(c);
}

void Runtime::post_drain(Connection& c) {
  c.drain_posted = true;
  auto drain_task = [](void* connection) {
    auto* c = static_cast<Connection*>(connection);
    c->runtime->drain(*c);
  };
  executor_->post_plain(now(), drain_task, &c);
}

// One message per task, so connections interleave fairly in posting order.
void Runtime::drain(Connection& c) {
  c.drain_posted = false;
  if (c.queue.empty()) return;
  Connection::Queued queued = c.queue.take_front();
  c.incoming_answered = queued.answered;
  c.message = queued.message;
  if (c.quarantined) {
    drop(c, DropReason::Quarantined);
  } else {
    c.judging_since = queued.arrived;
    process(c, queued.value);
    c.judging_since.reset();
  }
  if (!c.queue.empty() && !c.drain_posted) post_drain(c);
}

// --- the path ----------------------------------------------------------------------------

// What the monitor's protected call hands to after_accept, and what it leaves for process().
struct Runtime::Passing {
  Runtime* runtime;
  Connection* connection;
  Nanos t;
  bool refused = false;  // accepted, then not selected or throttled: `reason`, `detail`
  DropReason reason = DropReason::NotSelected;
  std::string detail;
};

// Between the monitor's accept and its update, inside its protected call (no Lua errors here).
bool Runtime::after_accept(void* passing, bool accepted) {
  auto* p = static_cast<Passing*>(passing);
  Runtime& rt = *p->runtime;
  Connection& c = *p->connection;
  c.fed = true;  // a feed's events now say what its source said (unknown_events.cc)
  c.answered = std::max(c.answered, c.incoming_answered);  // answered_deliveries.cc
  c.last_fed_at = rt.now();
  if (!accepted) return false;
  if (!rt.selected(c, p->t, &p->reason, &p->detail)) {
    p->refused = true;
    return false;
  }
  rt.busy_.enter("monitor", &c.name, "update");  // the BusyScope around the call leaves it
  return true;
}

// Steps 2 and 3 of the path: the constraint, on the container as accept left it, never on
// events not known yet; then the throttle, which counts deliveries, so only selected messages
// are throttled. False with the drop's reason and detail when the message goes no further.
bool Runtime::selected(Connection& c, Nanos t, DropReason* reason, std::string* detail) {
  *reason = DropReason::NotSelected;
  if (!c.unknown.empty() && !knows_events_of(c, detail)) return false;
  if (!c.feedback.empty() && !answered_events_of(c, t, detail)) return false;
  if (!c.constraint.evaluate(c.destination->container.present(t))) {
    if (c.is_feed) *reason = DropReason::Feed;
    return false;
  }
  if (c.throttle && t < c.last_delivery + *c.throttle) {  // exact: t and the period are integers
    *reason = DropReason::Throttled;
    return false;
  }
  return true;
}

// accept said false (with `reason`, maybe empty).
void Runtime::rejected(Connection& c, const std::string& reason) {
  c.consecutive_errors = 0;
  if (reason == drop_reason_name(DropReason::NoValue)) {
    drop(c, DropReason::NoValue, "accept");
  } else if (reason == drop_reason_name(DropReason::Throttled)) {
    drop(c, DropReason::Throttled, "accept");
  } else if (c.is_feed && reason.empty()) {
    drop(c, DropReason::Feed);  // a feed's accept may itself say "never deliver"
  } else {
    drop(c, DropReason::Rejected, reason);
  }
}

// The path: 1. accept, 2. the constraint, 3. the throttle, 4. update, then delivery. With a
// monitor, steps 1 to 4 run in one protected call into its script (LuaMonitor::pass).
void Runtime::process(Connection& c, const Value& msg) {
  Nanos t = now();
  if (!c.monitor || !(c.has_accept || c.has_update)) {
    DropReason reason;
    std::string detail;
    if (!selected(c, t, &reason, &detail)) {
      c.consecutive_errors = 0;
      drop(c, reason, detail);
      return;
    }
    deliver(c, t, msg);
    return;
  }
  Passing passing{this, &c, t, false, DropReason::NotSelected, {}};
  LuaMonitor::Passage passage;
  LuaCall call;
  {
    BusyScope busy(busy_, "monitor", c.name, "accept");
    call = c.monitor->pass(msg, *c.destination->type, c.has_update, &Runtime::after_accept,
                           &passing, &passage);
  }
  if (call.status == LuaCall::Status::NoValue) {
    c.consecutive_errors = 0;
    drop(c, DropReason::NoValue, passage.stage);
    return;
  }
  if (!call.ok()) {
    drop(c, DropReason::MonitorError, call.error);
    monitor_failed(c, call, passage.stage);
    return;
  }
  if (!passage.accepted) {
    rejected(c, passage.reason);
    return;
  }
  if (passing.refused) {
    c.consecutive_errors = 0;
    drop(c, passing.reason, passing.detail);
    return;
  }
  deliver(c, t, passage.updated ? passage.output : msg);
}

void Runtime::deliver(Connection& c, Nanos t, const Value& delivered) {
  c.consecutive_errors = 0;
  c.last_delivery = t;
  ++c.stats.delivered;
  if (trace_.enabled()) trace_.delivery(t, c.name, c.destination->qualified, delivered);
  // `by priority`: only a delivered message holds the lower rules off, for the event's
  // lifetime in app.json (the rule's hold); docs/design.md#priorities-and-holds.
  if (!c.model->activity_event.empty()) c.set_event(c.model->activity_event, std::nullopt);
  if (!c.model->delivery_sets.empty() || !c.model->delivery_unsets.empty())
    apply_delivery_effects(c, t);
  // Delivery events (docs/design.md#delivery-events): their feeds read what was delivered, in
  // this task, so no decision runs between a delivery and the events it sets.
  for (Connection* f : c.destination->delivery_feeds) {
    ++f->stats.arrived;
    f->message = c.message;
    process(*f, delivered);
  }
  save_memory();  // before the message leaves: runtime/mediator_memory.h
  Delivery d{c.destination->port, delivered, c.name, c.model->source, seconds_of(t)};
  if (c.destination->remote) delivered_to_remote(*c.destination->remote, t, c.message);
  if (loops_back_) {
    to_module(*c.destination, d);
  } else {
    transport_->deliver(c.destination->index, d);
  }
}

void Runtime::drop(Connection& c, DropReason reason, std::string_view detail) {
  ++c.stats.dropped[static_cast<int>(reason)];
  trace_.drop(now(), c.name, reason, detail);
  if (options_.report_bulk_drops && drop_reason_info(reason).loss && c.bulk.count(reason, 1, now()))
    report_bulk("connection " + c.name, reason);
}

void Runtime::report_bulk(const std::string& where, DropReason reason) {
  const DropReasonInfo& r = drop_reason_info(reason);
  report(where + ": losing messages in bulk from " + run_time_text(now()) + ", as " + r.name +
         " (" + r.meaning + "): " + std::to_string(BulkDrops::kThreshold) +
         " within a second; each is counted and traced, and this is said again only after a "
         "second without one");
}

void Runtime::monitor_failed(Connection& c, const LuaCall& call, const char* callback,
                             bool may_quarantine) {
  ++c.stats.errors;
  ++c.consecutive_errors;
  trace_.error(now(), c.name, call.error);
  if (c.reported_errors.insert(call.error).second) {
    report("connection " + c.name + ": " + callback + " failed: " + call.error +
           " (the message is dropped; this error is reported once)");
  }
  if (may_quarantine && !c.quarantined && c.consecutive_errors >= options_.quarantine_after) {
    quarantine(
        c, std::to_string(c.consecutive_errors) + " failures in a row, the last: " + call.error);
  }
}

void Runtime::quarantine(Connection& c, const std::string& why, bool destroy) {
  if (c.quarantined) return;
  c.quarantined = true;
  c.stats.quarantined = true;
  if (c.trig_task) executor_->cancel(c.trig_task);
  c.trig_task = 0;
  trace_.quarantine(now(), c.name, why);
  report("connection " + c.name + " quarantined: " + why +
         "; its messages are dropped from now on, the rest of the app keeps running");
  if (destroy && c.monitor) {
    BusyScope busy(busy_, "monitor", c.name, "destroy");
    c.monitor->destroy();  // its own failure changes nothing now
  }
}

void Runtime::schedule_trig(Connection& c, bool restart) {
  if (c.trig_task) executor_->cancel(c.trig_task);
  if (restart) {
    c.trig_start = now();
    c.trig_runs = 0;
  }
  ++c.trig_runs;
  // trig_runs intervals on, exactly; kNever once that would pass it (never reached in a run).
  uint64_t most = static_cast<uint64_t>((kNever - c.trig_start) / c.trig_interval);
  Nanos at = c.trig_runs > most
                 ? kNever
                 : c.trig_start + c.trig_interval * static_cast<int64_t>(c.trig_runs);
  c.trig_task = executor_->post(at, [this, &c] {
    c.trig_task = 0;
    if (c.quarantined || !c.monitor) return;
    LuaCall call;
    {
      BusyScope busy(busy_, "monitor", c.name, "trig");
      call = c.monitor->trig();
    }
    if (call.status == LuaCall::Status::Error) {
      monitor_failed(c, call, "trig");
    } else {
      c.consecutive_errors = 0;
    }
    if (!c.quarantined && c.trig_task == 0) schedule_trig(c, false);
  });
}

// --- PortMonitor calls -------------------------------------------------------------------

Nanos Runtime::Connection::now() { return runtime->now(); }

// What age() measures stamps against: while a message is judged, the ROS 2 time at its
// arrival, the same for every connection it feeds (one clock for the rules that judge it, as
// the proof assumes: verify/builtin_calls.cc); otherwise the time now.
Nanos Runtime::Connection::stamp_now() {
  if (!judging_since) return runtime->stamp_clock();
  return runtime->transport_clock_ ? *judging_since
                                   : runtime->executor().stamp_origin() + *judging_since;
}

// The run's clock as ROS 2 time: the transport's (the last /clock sample with DDS and
// --use-sim-time), else the executor's (Executor::stamp_origin).
Nanos Runtime::stamp_clock() const {
  if (transport_clock_) return *transport_->ros_time();
  return executor_->stamp_origin() + now();
}

// Without a lifetime, the one app.json declares for the event (none: until unset).
// `then set e` / `then unset e` (docs/language.md#events-set-on-delivery), in the task of the
// delivery as the activity event: a set is the rule's own entry, for the event's lifetime; an
// unset removes the entries that deliveries of the port's rules set (no monitor sets such an
// event: sema refuses it), which is what the proof's unrolling does.
void Runtime::apply_delivery_effects(Connection& c, Nanos t) {
  EventContainer& box = c.destination->container;
  for (const std::string& e : c.model->delivery_unsets) {
    box.present(t);  // lapse expired entries first, so the trace shows expiry before unset
    int id = box.index().find(e);
    // The trace names the owner of each entry removed (as a monitor's own unset does), which is
    // how the run's checks rebuild the container from it; the delivery just before says why.
    for (const auto& r : connections_)
      if (r->destination == c.destination && r->model->set_on_delivery(e) &&
          box.unset(id, r->index))
        trace_.event(t, c.destination->qualified, "unset", e, r->name, kNever);
  }
  // After the unsets, as the proof's unrolling has it: a rule that both unsets and sets an
  // event (an app.json written by hand; sema refuses it) leaves it set.
  for (const std::string& e : c.model->delivery_sets) c.set_event(e, std::nullopt);
}

void Runtime::Connection::set_event(std::string_view event, std::optional<Nanos> lifetime) {
  if (!lifetime) lifetime = runtime->declared_lifetime(event);
  Nanos t = runtime->now();
  EventContainer& box = destination->container;
  int id = box.index().intern(event);
  Nanos expiry = lifetime ? later(t, *lifetime) : kNever;
  box.set(id, index, expiry);
  runtime->trace_.event(t, destination->qualified, "set", event, name, expiry);
}

void Runtime::Connection::unset_event(std::string_view event) {
  Nanos t = runtime->now();
  EventContainer& box = destination->container;
  box.present(t);  // lapse expired entries first, so the trace shows expiry before unset
  if (box.unset(box.index().find(event), index)) {
    runtime->trace_.event(t, destination->qualified, "unset", event, name, kNever);
  }
}

bool Runtime::Connection::has_event(std::string_view event) {
  return destination->container.has(event, runtime->now());
}

// The constraint is app.json's (what the proof is about): the call only checks. The same
// formula (after parsing) passes silently; another one is refused, and remembered so that
// Runtime::create reports a call at load (top level or create) as bad input.
bool Runtime::Connection::set_constraint(std::string_view text, std::string* err) {
  std::optional<Constraint> parsed = parse_constraint(text, err);
  if (!parsed) {
    *err += " in \"" + std::string(text) + "\"";
    return false;
  }
  std::string wanted = parsed->to_string();
  if (wanted == constraint_text) return true;
  std::string why = "\"" + wanted + "\" would replace the constraint of connection '" +
                    model->name + "', \"" + constraint_text +
                    "\" (app.json's, which arbc verify proves and the runtime installs); remove "
                    "the call, or change the rule's `when` in the spec and rebuild";
  if (constraint_conflict.empty()) constraint_conflict = why;
  *err = why;
  return false;
}

void Runtime::Connection::set_trig_interval(Nanos interval) {
  trig_interval = interval;
  if (!quarantined && has_trig && runtime->started_) runtime->schedule_trig(*this, true);
}

void Runtime::Connection::print(const std::string& line) {
  runtime->trace_.log(runtime->now(), name, line);
  runtime->report(name + ": " + line);
}

}  // namespace arbc
