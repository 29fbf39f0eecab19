#include "verify/temporal/rates.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/duration_literal.h"
#include "core/time_text.h"

namespace arbc::verify::temporal {
namespace {

// An expression that cannot make the monitor fail: the message, its fields, literals, locals
// bound to such expressions, records and lists of them, ints of them converted to floats.
bool cannot_fail(const model::BodyExpr& e) {
  using Op = model::BodyExpr::Op;
  switch (e.op) {
    case Op::Message:
    case Op::Int:
    case Op::Float:
    case Op::String:
    case Op::Bool:
    case Op::Local:
      return true;
    case Op::Field:
    case Op::Record:
    case Op::List:
    case Op::ToFloat:
      for (const model::BodyExpr& a : e.args)
        if (!cannot_fail(a)) return false;
      return true;
    default:
      return false;
  }
}

}  // namespace

Rates::Rates(const model::App& app, const PortShape& shape, z3::context& ctx) : ctx_(ctx) {
  for (size_t c = 0; c < shape.connections.size(); ++c) {
    if (accepts_every_message(*shape.connections[c])) always_accept_.push_back(static_cast<int>(c));
    const model::SourceRate* r = app.find_rate(shape.connections[c]->source);
    if (!r) continue;
    rated_.push_back({static_cast<int>(c), nanos_term(ctx_, r->period), r->period});
    bool listed = false;
    for (const model::SourceRate& u : used_) listed |= u.port == r->port;
    if (!listed) used_.push_back(*r);
  }
}

z3::expr Rates::recent(const Unrolling& u, int c, const z3::expr& period, int n, const z3::expr& at,
                       bool strictly) const {
  auto within = [&](const z3::expr& gap) { return strictly ? gap < period : gap <= period; };
  z3::expr_vector any(ctx_);
  any.push_back(within(at));  // the first message is due by one period after the start
  for (int j = 0; j < n; ++j)
    any.push_back(u.runs(c, j) && u.time(j) <= at && within(at - u.time(j)));
  return z3::mk_or(any);
}

z3::expr Rates::up_to(const Unrolling& u, int n, const z3::expr& horizon, Horizon end) const {
  z3::expr_vector all(ctx_);
  for (const Rated& r : rated_) {
    // At each of its own steps (the gap before it) and at the horizon (the gap after the last).
    for (int k = 0; k < n; ++k)
      all.push_back(z3::implies(u.runs(r.connection, k),
                                recent(u, r.connection, r.period, k, u.time(k), false)));
    all.push_back(recent(u, r.connection, r.period, n, horizon, end == Horizon::Included));
  }
  return z3::mk_and(all);
}

Nanos Rates::span(int messages) const {
  if (rated_.empty()) return Nanos(0);
  // The multiples of the periods, in time order, until more than `messages` are due (in whole
  // nanoseconds, so two periods' coinciding multiples are one instant; kNever past 64 bits).
  std::vector<Nanos> due;
  for (const Rated& r : rated_)
    for (int64_t k = 1; k <= messages + 1; ++k)
      due.push_back(r.nanos.count() > kNever.count() / k ? kNever : k * r.nanos);
  std::sort(due.begin(), due.end());
  return due[static_cast<size_t>(messages)];
}

int Rates::due_by(Nanos t) const {
  int64_t n = 0;  // a multiple equal to t counts
  for (const Rated& r : rated_) n += t / r.nanos;
  return static_cast<int>(std::min<int64_t>(n, std::numeric_limits<int>::max()));
}

bool Rates::rated(int c) const {
  for (const Rated& r : rated_)
    if (r.connection == c) return true;
  return false;
}

z3::expr Rates::accepting(const Unrolling& u, int n) const {
  z3::expr_vector all(ctx_);
  for (int c : always_accept_)
    for (int k = 0; k < n; ++k) all.push_back(z3::implies(u.runs(c, k), u.accepts(k)));
  return z3::mk_and(all);
}

bool accepts_every_message(const model::Connection& c) {
  if (c.kind != model::ConnectionKind::Rule || c.opaque || !c.body) return false;
  for (const model::BodyStmt& s : *c.body) {
    bool safe = (s.kind == model::BodyStmt::Kind::Emit || s.kind == model::BodyStmt::Kind::Let) &&
                cannot_fail(s.expr);
    if (!safe) return false;
  }
  return true;
}

std::string rate_words(const model::SourceRate& r) {
  std::string where = r.loc.line ? " (" + r.loc.file + ":" + std::to_string(r.loc.line) + ")" : "";
  return "given " + r.port + " every " + duration_literal(r.period) + where;
}

}  // namespace arbc::verify::temporal
