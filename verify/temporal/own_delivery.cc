#include "verify/temporal/own_delivery.h"

#include <string>
#include <vector>

#include "core/event_facts.h"

namespace arbc::verify::temporal {
namespace {

using Op = model::BodyExpr::Op;

// Collects the body's `emit`s; false when some path ends without one (it delivers the message).
bool emits_on_every_path(const model::Body& body, std::vector<const model::BodyExpr*>& emits) {
  bool emitted = false;
  for (const model::BodyStmt& s : body) {
    if (s.kind == model::BodyStmt::Kind::Emit) {
      emits.push_back(&s.expr);
      emitted = true;
    } else if (s.kind == model::BodyStmt::Kind::If) {
      bool then_emits = emits_on_every_path(s.then_body, emits);
      bool else_emits = emits_on_every_path(s.else_body, emits);
      emitted = emitted || (then_emits && else_emits);
    }
  }
  return emitted;
}

bool literal(const model::BodyExpr& e) {
  return e.op == Op::Int || e.op == Op::String || e.op == Op::Bool || e.op == Op::Float;
}

// The part of `emitted` that `e` (over the delivered value) reads; null when not a literal path.
const model::BodyExpr* resolve(const model::BodyExpr& e, const model::BodyExpr& emitted) {
  if (e.op == Op::Message) return &emitted;
  if (literal(e)) return &e;
  if (e.op != Op::Field) return nullptr;
  const model::BodyExpr* base = resolve(e.args[0], emitted);
  if (!base || base->op != Op::Record) return nullptr;
  for (size_t i = 0; i < base->names.size(); ++i)
    if (base->names[i] == e.text) return &base->args[i];
  return nullptr;
}

// Two literals of one kind compared as Lua compares them (a float literal is a finite double).
std::optional<bool> equal(const model::BodyExpr* a, const model::BodyExpr* b) {
  if (!a || !b || !literal(*a) || a->op != b->op) return std::nullopt;
  switch (a->op) {
    case Op::Int:
      return a->integer == b->integer;
    case Op::String:
      return a->text == b->text;
    case Op::Bool:
      return a->boolean == b->boolean;
    default:
      return a->number == b->number;
  }
}

std::optional<bool> truth(const model::BodyExpr& p, const model::BodyExpr& emitted) {
  if (p.op == Op::Bool) return p.boolean;
  if (p.op == Op::Not) {
    std::optional<bool> a = truth(p.args[0], emitted);
    return a ? std::optional<bool>(!*a) : std::nullopt;
  }
  if (p.op != Op::Binary) return std::nullopt;
  if (p.text == "==" || p.text == "!=") {
    std::optional<bool> eq = equal(resolve(p.args[0], emitted), resolve(p.args[1], emitted));
    return eq ? std::optional<bool>(p.text == "==" ? *eq : !*eq) : std::nullopt;
  }
  if (p.text != "and" && p.text != "or") return std::nullopt;
  std::optional<bool> a = truth(p.args[0], emitted), b = truth(p.args[1], emitted);
  if (!a || !b) return std::nullopt;  // the right side unread may still fail: no shortcut
  return p.text == "and" ? *a && *b : *a || *b;
}

// Whether the data encoding is exact for `t`: no list (it bounds their length) and no float
// (it reads them as reals).
bool exact_type(const Type& t) {
  if (t.kind == Type::Kind::List || t.kind == Type::Kind::Float || t.kind == Type::Kind::Vec3)
    return false;
  for (const Field& f : t.fields)
    if (!exact_type(*f.type)) return false;
  return true;
}

// No arithmetic (the encoding's ints do not wrap), no builtin call, no list literal or index
// (Lua reads nil past a list's end where the encoding fails).
bool exact_expr(const model::BodyExpr& e) {
  if (e.op == Op::Neg || e.op == Op::Call || e.op == Op::ToFloat || e.op == Op::Float ||
      e.op == Op::List || e.op == Op::Index ||
      (e.op == Op::Binary && std::string("+-*/%").find(e.text) != std::string::npos))
    return false;
  for (const model::BodyExpr& a : e.args)
    if (!exact_expr(a)) return false;
  return true;
}

bool exact_body(const model::Body& body) {
  for (const model::BodyStmt& s : body)
    if (!exact_expr(s.expr) || !exact_body(s.then_body) || !exact_body(s.else_body)) return false;
  return true;
}

// Where the data encoding answers for every message the runtime can deliver.
bool data_exact(const model::App& app, const model::Connection& rule, const model::BodyExpr& p) {
  const model::Port* from = app.find_port(rule.source);
  const model::Port* to = app.find_port(rule.destination);
  return from && from->type && exact_type(*from->type) && to && to->type && exact_type(*to->type) &&
         exact_body(*rule.body) && exact_expr(p);
}

// What a delivery of `rule` can do to own delivery entry `e`; *may_fail when the feed's Lua may
// fail on it (the predicate reads a value that does not exist, or nothing says it cannot).
DeliveryOutcome outcome(const model::App& app, const model::Connection& rule, const Entry& e,
                        DataQuery* data, bool* may_fail) {
  bool lasts = e.lifetime.has_value();  // with `for D` a false predicate changes nothing
  DeliveryOutcome any{true, !lasts, true};
  if (rule.kind != model::ConnectionKind::Rule) return any;  // it never delivers
  if (rule.opaque || !rule.body || !e.predicate) {
    *may_fail = true;
    return any;
  }
  if (std::optional<bool> b = constant_outcome(rule, *e.predicate))
    return *b ? DeliveryOutcome{true, false, false} : DeliveryOutcome{false, !lasts, lasts};
  if (!data || !data_exact(app, rule, *e.predicate)) {
    *may_fail = true;
    return any;
  }
  DataQuery::PredicateRange r = data->predicate_range(rule, *e.predicate);
  *may_fail = *may_fail || r.can_fail;
  DeliveryOutcome o{r.can_true, !lasts && r.can_false, r.can_fail || (lasts && r.can_false)};
  if (!o.can_set && !o.can_unset && !o.can_keep) return any;  // no delivery at all: say nothing
  return o;
}

// At most this many events a rule's delivery may or may not set are asked about together
// (2^n questions per rule); more stay independent (more behaviours: sound).
constexpr size_t kMostJointOwnEvents = 4;

// The delivered value decides all of a rule's own delivery events at once: where the data
// encoding is exact and the feed cannot fail, a delivery sets exactly the events whose
// predicate holds, so a combination no value gives is excluded (two events over one verb are
// not set and left apart at will).
void exclude_joint_outcomes(const model::App& app, PortShape& shape, DataQuery& data) {
  for (size_t r = 0; r < shape.connections.size(); ++r) {
    const model::Connection& rule = *shape.connections[r];
    if (rule.kind != model::ConnectionKind::Rule || rule.opaque || !rule.body) continue;
    std::vector<size_t> free;
    for (size_t q = 0; q < shape.entries.size(); ++q) {
      const Entry& e = shape.entries[q];
      if (!e.own_delivery() || !e.predicate) continue;
      const DeliveryOutcome& o = e.on_delivery[r];
      if (o.can_set && (o.can_unset || o.can_keep) && data_exact(app, rule, *e.predicate))
        free.push_back(q);
    }
    if (free.size() < 2 || free.size() > kMostJointOwnEvents) continue;
    for (unsigned mask = 0; mask < (1u << free.size()); ++mask) {
      std::vector<DataSide> sides;
      for (size_t i = 0; i < free.size(); ++i)
        sides.push_back({&rule, shape.entries[free[i]].predicate, !(mask >> i & 1u)});
      if (data.ask(sides, nullptr, nullptr) != Answer::Unsat) continue;
      PortShape::ExcludedOutcome x{static_cast<int>(r), {}};
      for (size_t i = 0; i < free.size(); ++i) x.sets.emplace_back(free[i], (mask >> i & 1u) != 0);
      shape.excluded_outcomes.push_back(std::move(x));
    }
  }
}

}  // namespace

std::optional<bool> constant_outcome(const model::Connection& rule,
                                     const model::BodyExpr& predicate) {
  // A predicate that reads nothing of the value (`false`, `not true`) is what it is on every
  // delivery, whatever the rule emits: `truth` of it against a value it cannot read.
  model::BodyExpr unread;
  unread.op = Op::Local;
  if (std::optional<bool> fixed = truth(predicate, unread)) return fixed;
  std::vector<const model::BodyExpr*> emits;
  if (!rule.body || !emits_on_every_path(*rule.body, emits)) return std::nullopt;
  std::optional<bool> all;
  for (const model::BodyExpr* e : emits) {
    std::optional<bool> b = truth(predicate, *e);
    if (!b || (all && *all != *b)) return std::nullopt;
    all = b;
  }
  return all;
}

bool own_delivery_feed(const PortShape& shape, int c) {
  const model::Connection& f = *shape.connections[static_cast<size_t>(c)];
  return f.kind == model::ConnectionKind::Feed && f.source == shape.port;
}

void add_own_deliveries(const model::App& app, PortShape& shape, DataQuery* data) {
  bool may_fail = false;
  for (Entry& e : shape.entries) {
    if (!own_delivery_feed(shape, e.owner) ||
        !model::is_delivery_feed(app, *shape.connections[static_cast<size_t>(e.owner)]))
      continue;
    const model::Event* event = app.find_event(e.event);
    e.predicate = event && event->predicate ? &*event->predicate : nullptr;
    for (const model::Connection* c : shape.connections)
      e.on_delivery.push_back(outcome(app, *c, e, data, &may_fail));
  }
  // One feed evaluates every own delivery event of the port, in one Lua call: when it may fail
  // on some delivery, the events after the failing one keep their state, and failures in a row
  // quarantine it (runtime/message_path.cc), after which no delivery changes any of them.
  if (!may_fail) {
    if (data) exclude_joint_outcomes(app, shape, *data);
    return;
  }
  for (Entry& e : shape.entries)
    for (DeliveryOutcome& o : e.on_delivery) o.can_keep = true;
}

void Unrolling::add_excluded_outcomes(int k) {
  for (const PortShape::ExcludedOutcome& x : shape_.excluded_outcomes) {
    z3::expr pattern = ctx_.bool_val(true);
    for (const auto& [q, set] : x.sets) pattern = pattern && set_[k][q] == ctx_.bool_val(set);
    // A feed's combination at each of its messages; a delivery's at each delivery.
    z3::expr when = x.feed ? run_[k] == x.rule : del_[k][static_cast<size_t>(x.rule)];
    solver_.add(z3::implies(when, !pattern));
  }
}

bool Unrolling::has_own_deliveries() const {
  for (const Entry& e : shape_.entries)
    if (e.own_delivery()) return true;
  return false;
}

z3::expr Unrolling::order_before_start(int c) const {
  return ctx_.int_const(("order0!" + std::to_string(c)).c_str());
}

// Step k changes the entry only if a rule delivers at it, as that rule's outcome allows. The
// entry's state k+1 is read by step k+1's decision, never by step k's (Unrolling::present).
void Unrolling::add_own_delivery_step(size_t q, int k) {
  const Entry& e = shape_.entries[q];
  z3::expr set = set_[k][q], unset = unset_[k][q];
  z3::expr_vector delivery(ctx_);
  for (size_t c = 0; c < shape_.connections.size(); ++c) {
    const z3::expr& d = del_[k][c];
    const DeliveryOutcome& o = e.on_delivery[c];
    delivery.push_back(d);
    if (!o.can_set) solver_.add(z3::implies(d, !set));
    if (!o.can_unset) solver_.add(z3::implies(d, !unset));
    if (!o.can_keep) solver_.add(z3::implies(d, set || unset));
  }
  solver_.add(z3::implies(set || unset, z3::mk_or(delivery)));
  solver_.add(!(set && unset));
  add_entry_update(q, k);
}

namespace {

bool must_set(const DeliveryOutcome& o) { return o.can_set && !o.can_unset && !o.can_keep; }
bool must_unset(const DeliveryOutcome& o) { return o.can_unset && !o.can_set && !o.can_keep; }

}  // namespace

// Any state (k-induction's step case) as some run leaves it: the rules' last deliveries before
// step 1 came one after the other (order0), at times in that order; an own delivery entry is
// there only if a rule that can set it delivered, after every last delivery of a rule that
// must unset it (with `for D`: it lapses D after that delivery at the latest), and a rule that
// must set it leaves it there (for D from its last delivery at least) unless a later delivery
// may have removed it. A run's state satisfies all of this, so no real state is excluded.
void Unrolling::constrain_own_deliveries_at_start() {
  std::vector<int> rules;
  for (size_t c = 0; c < shape_.connections.size(); ++c)
    if (shape_.connections[c]->kind == model::ConnectionKind::Rule)
      rules.push_back(static_cast<int>(c));
  for (size_t i = 0; i < rules.size(); ++i) {
    for (size_t j = i + 1; j < rules.size(); ++j) {
      int a = rules[i], b = rules[j];
      z3::expr oa = order_before_start(a), ob = order_before_start(b);
      z3::expr la = last_delivery_before_start(a), lb = last_delivery_before_start(b);
      solver_.add(z3::implies(
          delivered_before_start(a) && delivered_before_start(b),
          oa != ob && z3::implies(oa < ob, la <= lb) && z3::implies(ob < oa, lb <= la)));
    }
  }
  // Every rule r2 (but r) that `which` picks delivered last before r's last delivery, if at all.
  auto after = [&](int r, const Entry& e, bool (*which)(const DeliveryOutcome&)) {
    z3::expr all = ctx_.bool_val(true);
    for (int r2 : rules)
      if (r2 != r && which(e.on_delivery[static_cast<size_t>(r2)]))
        all = all && z3::implies(delivered_before_start(r2),
                                 order_before_start(r2) < order_before_start(r));
    return all;
  };
  auto can_set = [](const DeliveryOutcome& o) { return o.can_set; };
  auto can_unset = [](const DeliveryOutcome& o) { return o.can_unset; };
  for (size_t q = 0; q < shape_.entries.size(); ++q) {
    const Entry& e = shape_.entries[q];
    if (!e.own_delivery()) continue;
    const z3::expr &has = has_[0][q], &expiry = expiry_[0][q];
    z3::expr_vector setters(ctx_);
    for (int r : rules) {
      const DeliveryOutcome& o = e.on_delivery[static_cast<size_t>(r)];
      z3::expr last = last_delivery_before_start(r);
      z3::expr by =
          e.lifetime ? expiry <= last + nanos_term(ctx_, *e.lifetime) : after(r, e, must_unset);
      if (o.can_set) setters.push_back(delivered_before_start(r) && by);
      if (must_set(o) && e.lifetime)
        solver_.add(z3::implies(delivered_before_start(r),
                                has && expiry >= last + nanos_term(ctx_, *e.lifetime)));
      if (must_set(o) && !e.lifetime)
        solver_.add(z3::implies(delivered_before_start(r) && after(r, e, can_unset), has));
      if (must_unset(o))
        solver_.add(z3::implies(delivered_before_start(r) && after(r, e, can_set), !has));
    }
    solver_.add(z3::implies(has, z3::mk_or(setters)));
  }
}

}  // namespace arbc::verify::temporal
