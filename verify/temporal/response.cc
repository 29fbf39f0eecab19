#include "verify/temporal/response.h"

#include <algorithm>

#include "core/duration_literal.h"
#include "core/join.h"
#include "core/time_text.h"
#include "verify/temporal/bmc.h"
#include "verify/temporal/constraint_expr.h"
#include "verify/temporal/rates.h"

namespace arbc::verify::temporal {
namespace {

// The step whose trigger a violation over n steps leaves unanswered (for the explanation).
z3::expr trigger_step(z3::context& ctx, int n) {
  return ctx.int_const(("trigger!" + std::to_string(n)).c_str());
}

struct Pieces {
  int rule, trigger;  // rule -1: any rule of the port answers; trigger -1: p.event's onset
  const model::TemporalProperty& p;
  const Rates& rates;
  std::vector<int> answers;  // the connections whose delivery answers: the rule, or every rule
};

z3::expr triggered(const Unrolling& u, const Pieces& w, int i) {
  return w.trigger >= 0 ? u.delivers(w.trigger, i) : u.becomes_present(w.p.event, i);
}

// The trigger at step i and none of what discharges it in steps i+1..n-1: a delivery that
// answers, or (with `stops`) another of the trigger; the condition at each answering rule's step.
z3::expr unanswered_from(const Unrolling& u, const Pieces& w, int i, int n, z3::context& ctx) {
  z3::expr_vector all(ctx);
  all.push_back(triggered(u, w, i));
  for (int j = i + 1; j < n; ++j) {
    z3::expr c = constraint_expr(w.p.condition, ctx,
                                 [&](const std::string& e) { return u.present_at_decision(e, j); });
    for (int a : w.answers) {
      all.push_back(!u.delivers(a, j));
      all.push_back(z3::implies(u.runs(a, j), c));
    }
    if (w.p.stops) all.push_back(!u.delivers(w.trigger, j));
  }
  return z3::mk_and(all);
}

// Violated over the first n steps: some trigger i left unanswered until the horizon
// t_i + D, which no step passes, under the rates up to the horizon. The horizon is a fresh
// integer per n (the formula lives inside bounded_search's push/pop).
z3::expr violation(const Unrolling& u, const Pieces& w, int n, z3::context& ctx) {
  z3::expr horizon = ctx.int_const(("horizon!" + std::to_string(n)).c_str());
  z3::expr_vector some(ctx);
  for (int i = 0; i < n; ++i)
    some.push_back(trigger_step(ctx, n) == i &&
                   horizon == u.time(i) + nanos_term(ctx, w.p.window) &&
                   unanswered_from(u, w, i, n, ctx));
  z3::expr_vector all(ctx);
  all.push_back(z3::mk_or(some));
  all.push_back(u.time(n - 1) <= horizon);
  all.push_back(w.rates.up_to(u, n, horizon, Rates::Horizon::Included));
  all.push_back(w.rates.accepting(u, n));
  return z3::mk_and(all);
}

// For a violated trace: the trigger (step i) left unanswered, when its window closed, and the
// answering rules' sources without a rate (without one, a source may simply fall silent).
std::string explain(const TemporalResult& r, const model::TemporalProperty& p, size_t i,
                    const std::vector<std::string>& unrated) {
  std::string answer = p.rule.empty() ? "any rule of " + p.port : "'" + p.rule + "'";
  std::string out;
  if (i < r.trace.size())
    out = (p.event.empty() ? "'" + p.other + "' delivered" : p.event + " became present") + " at " +
          duration_literal(r.trace[i].time) + " and time reached " +
          duration_literal(r.trace[i].time + p.window) + " with no delivery of " + answer;
  if (!unrated.empty()) {
    bool one = unrated.size() == 1;
    out += "; no rate is given for " + join(unrated) + ", the source" + (one ? "" : "s") + " of " +
           answer + (one ? ", so it may fall silent" : ", so they may fall silent") +
           ", and silence violates a response: if " + (one ? "it publishes" : "they publish") +
           " periodically, say so with `given " + unrated.front() + " every D;`";
  }
  return out;
}

}  // namespace

std::optional<TemporalResult> check_response(const model::App& app,
                                             const model::TemporalProperty& p, int bound,
                                             z3::context& ctx, DataQuery* data,
                                             std::chrono::steady_clock::time_point deadline,
                                             std::string* err, bool faithful) {
  std::optional<PropertyShape> ps = property_shape(app, p, err, faithful, data);
  if (!ps) return std::nullopt;
  const PortShape* shape = &ps->shape;
  if (!p.event.empty() && !sets_into(*shape, p.event)) {
    // Nothing puts the event into the port's container, so no window ever opens.
    TemporalResult vacuous;
    vacuous.property = p;
    vacuous.outcome = TemporalResult::Outcome::Vacuous;
    vacuous.proof = "nothing sets " + p.event + " into " + p.port +
                    ", so it never becomes present there and no window opens";
    return vacuous;
  }
  Rates rates(app, *shape, ctx);
  Pieces w{ps->rule, ps->other, p, rates, {}};
  // Silence may be all a violation needs when no answering rule's source has a rate: then
  // the explanation names them.
  std::vector<std::string> unrated;
  bool rated = false;
  for (size_t c = 0; c < shape->connections.size(); ++c) {
    const model::Connection& conn = *shape->connections[c];
    if (conn.kind != model::ConnectionKind::Rule) continue;
    if (w.rule >= 0 && static_cast<int>(c) != w.rule) continue;
    w.answers.push_back(static_cast<int>(c));
    rated |= app.find_rate(conn.source) != nullptr;
    if (std::find(unrated.begin(), unrated.end(), conn.source) == unrated.end())
      unrated.push_back(conn.source);
  }
  if (rated) unrated.clear();
  size_t trigger = 0;
  TemporalResult result = bounded_search(
      *shape, p, 1, bound, [&](const Unrolling& u, int n) { return violation(u, w, n, ctx); }, ctx,
      data, deadline,
      [&](const z3::model& m, int n) {
        trigger = static_cast<size_t>(m.eval(trigger_step(ctx, n), true).get_numeral_int());
      });
  result.rates = rates.used();
  if (result.outcome == TemporalResult::Outcome::HoldsToBound)
    result.rated_span = rates.span(result.bound);
  if (!rates.empty()) {
    bool trigger_is_rated = w.trigger < 0 || rates.rated(w.trigger);  // an event: by a feed
    result.window_bound = rates.due_by(p.window) + (trigger_is_rated ? 0 : 1);
  }
  if (result.outcome == TemporalResult::Outcome::Violated)
    result.explanation = explain(result, p, trigger, unrated);
  return result;
}

}  // namespace arbc::verify::temporal
