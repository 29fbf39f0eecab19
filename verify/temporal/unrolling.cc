#include "verify/temporal/unrolling.h"

#include <algorithm>
#include <cstdlib>
#include <set>

#include "verify/temporal/constraint_expr.h"
#include "verify/temporal/feed_outcomes.h"
#include "verify/temporal/own_delivery.h"

namespace arbc::verify::temporal {
namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

// The lifetimes the `set event` statements of a body give: `for D`, or the event's declared
// lifetime (none: until unset). False when a statement of `event` is not in `body`'s reach
// (never: the caller checks); `out` collects one entry per distinct lifetime.
void set_lifetimes(const model::Body& body, const std::string& event, std::optional<Nanos> declared,
                   std::vector<std::optional<Nanos>>& out) {
  for (const model::BodyStmt& s : body) {
    if (s.kind == model::BodyStmt::Kind::Set && s.name == event) {
      std::optional<Nanos> life = s.lifetime ? s.lifetime : declared;
      if (std::find(out.begin(), out.end(), life) == out.end()) out.push_back(life);
    }
    set_lifetimes(s.then_body, event, declared, out);
    set_lifetimes(s.else_body, event, declared, out);
  }
}

// How long an entry the connection sets lives (docs/design.md#properties-over-time).
Entry entry_of(const model::App& app, const model::Connection& c, const std::string& event,
               int owner) {
  Entry e;
  e.event = event;
  e.owner = owner;
  const model::Event* declared = app.find_event(event);
  std::optional<Nanos> lifetime = declared ? declared->lifetime : std::nullopt;
  if (c.set_on_delivery(event)) {
    e.activity = true;
    e.lifetime = lifetime;  // the rule's hold, or the lifetime of `then set`'s event
  } else if (c.kind == model::ConnectionKind::Feed) {
    e.lifetime = lifetime;  // `events from ... lifetime D`, a derived event's `for D`
    if (declared && declared->predicate && declared->predicate->op == model::BodyExpr::Op::Bool)
      e.constant_predicate = declared->predicate->boolean;
  } else {
    // `set e [for D]` in the rule's body: the lifetime every such statement gives, as the
    // runtime applies it. Without the body (a script), or with statements that differ, any
    // lifetime: more behaviours, and a counterexample that needs one is replayed to be sure.
    std::vector<std::optional<Nanos>> lifetimes;
    if (c.body && !c.opaque) set_lifetimes(*c.body, event, lifetime, lifetimes);
    if (lifetimes.size() == 1) {
      e.lifetime = lifetimes[0];
    } else {
      e.free_lifetime = true;
    }
  }
  return e;
}

}  // namespace

z3::expr nanos_term(z3::context& ctx, Nanos d) { return ctx.int_val(int64_t{d.count()}); }

std::optional<PortShape> port_shape(const model::App& app, const std::string& port,
                                    std::string* err, DataQuery* data) {
  if (!app.find_arbitrated(port)) {
    *err = port + " is not an arbitrated port of app " + app.name;
    return std::nullopt;
  }
  PortShape shape;
  shape.port = port;
  std::set<std::string> events;
  for (const model::Connection* c : app.connections_into(port)) {
    if (c->kind == model::ConnectionKind::Connect) continue;
    int owner = static_cast<int>(shape.connections.size());
    shape.connections.push_back(c);
    c->constraint.collect_events(events);
    for (const std::string& e : c->sets) {
      shape.entries.push_back(entry_of(app, *c, e, owner));
      events.insert(e);
    }
  }
  // A `script` rule's Lua is not analysed: its `sets` are only the names it passes to setEvent
  // as literals, and a name it computes may be any event of the port. So it owns an entry of
  // every event the port reads, set and removed freely (a counterexample that needs one is
  // unknown: the replay cannot make the script do it).
  for (size_t owner = 0; owner < shape.connections.size(); ++owner) {
    const model::Connection& c = *shape.connections[owner];
    if (!c.opaque) continue;
    for (const std::string& e : events)
      if (!contains(c.sets, e) && e != c.activity_event)
        shape.entries.push_back(entry_of(app, c, e, static_cast<int>(owner)));
  }
  // `then unset e`: its delivery removes every entry of e that deliveries set.
  for (Entry& entry : shape.entries) {
    if (!entry.activity) continue;
    for (size_t c = 0; c < shape.connections.size(); ++c)
      if (contains(shape.connections[c]->delivery_unsets, entry.event))
        entry.unset_by.push_back(static_cast<int>(c));
  }
  add_own_deliveries(app, shape, data);
  add_feed_outcomes(app, shape, data);
  shape.events.assign(events.begin(), events.end());
  if (!add_port_assumptions(app, shape, err)) return std::nullopt;
  return shape;
}

Unrolling::Unrolling(const PortShape& shape, int steps, z3::context& ctx, z3::solver& solver,
                     Start start)
    : shape_(shape), ctx_(ctx), solver_(solver), start_(start) {
  start_state();
  for (int k = 0; k < steps; ++k) add_step(k);
}

// State 0: the empty container, or (k-induction's step case) any state.
void Unrolling::start_state() {
  has_.emplace_back();
  forever_.emplace_back();
  expiry_.emplace_back();
  for (size_t q = 0; q < shape_.entries.size(); ++q) {
    if (start_ == Start::AnyState) {
      add_any_start_entry(q);
      continue;
    }
    has_[0].push_back(ctx_.bool_val(false));
    forever_[0].push_back(ctx_.bool_val(false));
    expiry_[0].push_back(ctx_.int_val(0));
  }
  if (start_ == Start::AnyState) constrain_feeds_at_start();
}

// Step k: its time, connection and accept outcome; the entries it changes; the deliveries.
void Unrolling::add_step(int k) {
  std::string s = "!" + std::to_string(k);
  t_.push_back(ctx_.int_const(("t" + s).c_str()));
  solver_.add(k == 0 ? t_[k] >= 0 : t_[k] >= t_[k - 1]);
  if (k == 0 && start_ == Start::AnyState) constrain_any_start();
  run_.push_back(ctx_.int_const(("run" + s).c_str()));
  solver_.add(run_[k] >= 0 && run_[k] < static_cast<int>(shape_.connections.size()));
  acc_.push_back(ctx_.bool_const(("acc" + s).c_str()));
  has_.emplace_back();
  forever_.emplace_back();
  expiry_.emplace_back();
  set_.emplace_back();
  unset_.emplace_back();
  for (size_t q = 0; q < shape_.entries.size(); ++q) {
    std::string e = "!" + std::to_string(q) + s;
    has_[k + 1].push_back(ctx_.bool_const(("has" + e).c_str()));
    forever_[k + 1].push_back(ctx_.bool_const(("forever" + e).c_str()));
    expiry_[k + 1].push_back(ctx_.int_const(("expiry" + e).c_str()));
    set_[k].push_back(ctx_.bool_const(("set" + e).c_str()));
    unset_[k].push_back(ctx_.bool_const(("unset" + e).c_str()));
  }
  for (size_t q = 0; q < shape_.entries.size(); ++q) {
    if (!shape_.entries[q].activity && !shape_.entries[q].own_delivery()) add_entry_step(q, k);
  }
  del_.emplace_back();
  for (size_t c = 0; c < shape_.connections.size(); ++c) {
    const model::Connection& conn = *shape_.connections[c];
    z3::expr d = ctx_.bool_const(("del!" + std::to_string(c) + s).c_str());
    z3::expr selected = run_[k] == static_cast<int>(c) && acc_[k] && guard(conn.constraint, k);
    if (conn.kind != model::ConnectionKind::Rule) selected = ctx_.bool_val(false);
    // The feed of the port's own delivery events runs inside its deliveries only.
    if (own_delivery_feed(shape_, static_cast<int>(c))) solver_.add(run_[k] != static_cast<int>(c));
    if (conn.throttle) {  // dropped while t < last delivery + period (runtime/message_path.cc)
      z3::expr period = nanos_term(ctx_, *conn.throttle);
      for (int i = 0; i < k; ++i)
        selected = selected && z3::implies(del_[i][c], t_[k] - t_[i] >= period);
      if (start_ == Start::AnyState)
        selected = selected &&
                   z3::implies(delivered_before_start(static_cast<int>(c)),
                               t_[k] - last_delivery_before_start(static_cast<int>(c)) >= period);
    }
    solver_.add(d == selected);
    del_[k].push_back(d);
  }
  for (size_t q = 0; q < shape_.entries.size(); ++q) {
    if (shape_.entries[q].activity) add_activity_step(q, k);
    if (shape_.entries[q].own_delivery()) add_own_delivery_step(q, k);
  }
  add_excluded_outcomes(k);
  add_assumptions(k);
  if (shape_.faithful) add_faithful(k);
}

// An entry the running connection's monitor may set or remove (must, on an accepting step).
void Unrolling::add_entry_step(size_t q, int k) {
  const Entry& e = shape_.entries[q];
  const model::Connection& c = *shape_.connections[static_cast<size_t>(e.owner)];
  z3::expr running = run_[k] == e.owner;
  z3::expr set = set_[k][q], unset = unset_[k][q];
  bool must_set = contains(c.must_set, e.event), must_unset = contains(c.must_unset, e.event);
  solver_.add(z3::implies(set, running));
  bool may_unset = c.opaque || contains(c.unsets, e.event);  // a script's names are not all known
  solver_.add(may_unset ? z3::implies(unset, running) : !unset);
  solver_.add(!(set && unset));
  if (must_set && !must_unset) solver_.add(z3::implies(running && acc_[k], set));
  if (must_unset && !must_set) solver_.add(z3::implies(running && acc_[k], unset));
  // Each message of the source sets it or (without `for D` on a derived event) removes it.
  if (e.by_message)
    solver_.add(z3::implies(running, e.predicate && e.lifetime ? !unset : set || unset));
  add_entry_update(q, k);
}

// State k+1 of entry q: as step k's set or unset leaves it (with its lifetime from t_k).
void Unrolling::add_entry_update(size_t q, int k) {
  const Entry& e = shape_.entries[q];
  z3::expr set = set_[k][q], unset = unset_[k][q];
  const z3::expr &h0 = has_[k][q], &f0 = forever_[k][q], &x0 = expiry_[k][q];
  const z3::expr &h1 = has_[k + 1][q], &f1 = forever_[k + 1][q], &x1 = expiry_[k + 1][q];
  solver_.add(h1 == z3::ite(set, ctx_.bool_val(true), z3::ite(unset, ctx_.bool_val(false), h0)));
  solver_.add(z3::implies(!set, f1 == f0 && x1 == x0));
  if (e.free_lifetime) {
    solver_.add(z3::implies(set, x1 > t_[k]));  // any lifetime, or none (f1 free)
  } else if (e.lifetime) {
    solver_.add(z3::implies(set, !f1 && x1 == t_[k] + nanos_term(ctx_, *e.lifetime)));
  } else {
    solver_.add(z3::implies(set, f1 && x1 == t_[k]));
  }
}

// An entry the runtime sets as its rule delivers (a `by priority` activity event, `then set`):
// set for its lifetime each time the rule delivers, removed only by a `then unset` delivery.
void Unrolling::add_activity_step(size_t q, int k) {
  const Entry& e = shape_.entries[q];
  z3::expr d = del_[k][static_cast<size_t>(e.owner)];
  const z3::expr &h0 = has_[k][q], &f0 = forever_[k][q], &x0 = expiry_[k][q];
  const z3::expr &h1 = has_[k + 1][q], &f1 = forever_[k + 1][q], &x1 = expiry_[k + 1][q];
  if (e.unset_by.empty()) {  // the terms as before `then unset`: the same models, the same goldens
    solver_.add(set_[k][q] == d && !unset_[k][q]);
    solver_.add(h1 == (d || h0));
  } else {
    z3::expr removed = ctx_.bool_val(false);
    for (int u : e.unset_by) removed = removed || del_[k][static_cast<size_t>(u)];
    solver_.add(set_[k][q] == d && unset_[k][q] == (removed && !d));
    solver_.add(h1 == (d || (h0 && !removed)));
  }
  solver_.add(z3::implies(!d, f1 == f0 && x1 == x0));
  if (e.lifetime) {
    solver_.add(z3::implies(d, !f1 && x1 == t_[k] + nanos_term(ctx_, *e.lifetime)));
  } else {
    solver_.add(z3::implies(d, f1 && x1 == t_[k]));
  }
}

// `event` is present at step k's decision: the entries as accept left them (activity and own
// delivery entries as before the step: they change only after the decision), at time t_k.
z3::expr Unrolling::present(const std::string& event, int k, const z3::expr& at) const {
  z3::expr any = ctx_.bool_val(false);
  for (size_t q = 0; q < shape_.entries.size(); ++q) {
    const Entry& e = shape_.entries[q];
    if (e.event != event) continue;
    size_t s = static_cast<size_t>(e.activity || e.own_delivery() ? k : k + 1);
    any = any || (has_[s][q] && (forever_[s][q] || at < expiry_[s][q]));
  }
  return any;
}

z3::expr Unrolling::becomes_present(const std::string& event, int k) const {
  z3::expr before = ctx_.bool_val(false), after = ctx_.bool_val(false);
  for (size_t q = 0; q < shape_.entries.size(); ++q) {
    if (shape_.entries[q].event != event) continue;
    auto in = [&](size_t s) { return has_[s][q] && (forever_[s][q] || t_[k] < expiry_[s][q]); };
    before = before || in(static_cast<size_t>(k));
    after = after || in(static_cast<size_t>(k + 1));
  }
  return !before && after;
}

z3::expr Unrolling::guard(const Constraint& c, int k) const {
  return constraint_expr(c, ctx_, [&](const std::string& e) { return present(e, k, t_[k]); });
}

int rule_index(const PortShape& shape, const std::string& rule) {
  for (size_t i = 0; i < shape.connections.size(); ++i) {
    const model::Connection& c = *shape.connections[i];
    if (c.kind == model::ConnectionKind::Rule && c.name == rule) return static_cast<int>(i);
  }
  return -1;
}

bool sets_into(const PortShape& shape, const std::string& event) {
  for (const Entry& e : shape.entries)
    if (e.event == event) return true;
  return false;
}

namespace {

// A time in `m`, kNever beyond 64 bits (a free expiry the solver put far away).
Nanos time_in(const z3::model& m, const z3::expr& e) {
  z3::expr ns = m.eval(e, true);
  int64_t n = 0;
  if (ns.is_numeral_i64(n)) return Nanos(n);
  return ns.is_numeral() && ns.as_double() < 0 ? -kNever : kNever;
}

}  // namespace

Nanos Unrolling::time_value(const z3::model& m, int k) const { return time_in(m, t_[k]); }

int Unrolling::connection(const z3::model& m, int k) const {
  return m.eval(run_[k], true).get_numeral_int();
}

bool Unrolling::accepted(const z3::model& m, int k) const {
  return m.eval(acc_[k], true).is_true();
}

Unrolling::EntryValue Unrolling::entry(const z3::model& m, int state, size_t q) const {
  size_t s = static_cast<size_t>(state);
  return {m.eval(has_[s][q], true).is_true(), m.eval(forever_[s][q], true).is_true(),
          time_in(m, expiry_[s][q])};
}

bool Unrolling::changes(const z3::model& m, int k, size_t q) const {
  return m.eval(set_[k][q], true).is_true() || m.eval(unset_[k][q], true).is_true();
}

TraceStep Unrolling::trace_step(const z3::model& m, int k) const {
  TraceStep step;
  step.time = time_value(m, k);
  int c = connection(m, k);
  const model::Connection& conn = *shape_.connections[static_cast<size_t>(c)];
  step.connection = conn.name;
  step.source = conn.source;
  step.feed = conn.kind == model::ConnectionKind::Feed;
  step.accepted = accepted(m, k);
  step.delivered = m.eval(del_[k][static_cast<size_t>(c)], true).is_true();
  for (size_t q = 0; q < shape_.entries.size(); ++q) {
    // An own delivery event changes in the step of the delivery that sets it; its unset is
    // shown only where there was an entry to remove (the runtime traces no other).
    // A `then unset` removes another rule's entry, likewise shown where there was one.
    const Entry& e = shape_.entries[q];
    bool removes = std::find(e.unset_by.begin(), e.unset_by.end(), c) != e.unset_by.end();
    if (e.owner != c && !e.own_delivery() && !removes) continue;
    if (m.eval(set_[k][q], true).is_true()) step.set.push_back(e.event);
    if (m.eval(unset_[k][q], true).is_true() &&
        ((!e.own_delivery() && !removes) ||
         m.eval(has_[static_cast<size_t>(k)][q], true).is_true()) &&
        !contains(step.unset, e.event))
      step.unset.push_back(e.event);
  }
  return step;
}

}  // namespace arbc::verify::temporal
