#include "verify/temporal/response.h"

#include "core/time_text.h"
#include "verify/temporal/bmc.h"
#include "verify/temporal/constraint_expr.h"
#include "verify/temporal/rates.h"

namespace arbc::verify::temporal {
namespace {

struct Pieces {
  int rule, trigger;
  const model::TemporalProperty& p;
  const Rates& rates;
};

// The trigger at step i and none of what discharges it in steps i+1..n-1: a delivery of the
// rule, or (with `stops`) another of the trigger; the condition at each of the rule's steps.
z3::expr unanswered_from(const Unrolling& u, const Pieces& w, int i, int n, z3::context& ctx) {
  z3::expr_vector all(ctx);
  all.push_back(u.delivers(w.trigger, i));
  for (int j = i + 1; j < n; ++j) {
    all.push_back(!u.delivers(w.rule, j));
    if (w.p.stops) all.push_back(!u.delivers(w.trigger, j));
    z3::expr c = constraint_expr(w.p.condition, ctx,
                                 [&](const std::string& e) { return u.present_at_decision(e, j); });
    all.push_back(z3::implies(u.runs(w.rule, j), c));
  }
  return z3::mk_and(all);
}

// Violated over the first n steps: some trigger i left unanswered until the horizon
// t_i + D, which no step passes, under the rates up to the horizon. The horizon is a fresh
// real per n (the formula lives inside bounded_search's push/pop).
z3::expr violation(const Unrolling& u, const Pieces& w, int n, z3::context& ctx) {
  z3::expr horizon = ctx.real_const(("horizon!" + std::to_string(n)).c_str());
  z3::expr_vector some(ctx);
  for (int i = 0; i < n; ++i)
    some.push_back(horizon == u.time(i) + seconds(ctx, w.p.window) &&
                   unanswered_from(u, w, i, n, ctx));
  z3::expr_vector all(ctx);
  all.push_back(z3::mk_or(some));
  all.push_back(u.time(n - 1) <= horizon);
  all.push_back(w.rates.up_to(u, n, horizon, Rates::Horizon::Included));
  all.push_back(w.rates.accepting(u, n));
  return z3::mk_and(all);
}

// For a violated trace: the trigger left unanswered, when its window closed, and whether
// the rule's source had a rate (without one, the source may simply fall silent).
std::string explain(const TemporalResult& r, const model::TemporalProperty& p,
                    const model::Connection& rule, bool rated) {
  const std::vector<TraceStep>& trace = r.trace;
  std::string out;
  for (size_t i = 0; i < trace.size() && out.empty(); ++i) {
    if (trace[i].connection != p.other || !trace[i].delivered) continue;
    bool answered = false;
    for (size_t j = i + 1; j < trace.size(); ++j)
      answered |= trace[j].delivered &&
                  (trace[j].connection == p.rule || (p.stops && trace[j].connection == p.other));
    if (answered) continue;
    out = "'" + p.other + "' delivered at " + time_text(trace[i].time) + "s and time reached " +
          time_text(trace[i].time + p.window) + "s with no delivery of '" + p.rule + "'";
  }
  if (!rated)
    out += "; no rate is given for " + rule.source + ", the source of '" + p.rule +
           "', so it may fall silent, and silence violates a response: if it publishes "
           "periodically, say so with `given " +
           rule.source + " every D;`";
  return out;
}

}  // namespace

std::optional<TemporalResult> check_response(const model::App& app,
                                             const model::TemporalProperty& p, int bound,
                                             z3::context& ctx, DataQuery* data,
                                             std::chrono::steady_clock::time_point deadline,
                                             std::string* err) {
  std::optional<PropertyShape> ps = property_shape(app, p, err);
  if (!ps) return std::nullopt;
  const PortShape* shape = &ps->shape;
  int r = ps->rule, o = ps->other;
  Rates rates(app, *shape, ctx);
  Pieces w{r, o, p, rates};
  TemporalResult result = bounded_search(
      *shape, p, 1, bound, [&](const Unrolling& u, int n) { return violation(u, w, n, ctx); }, ctx,
      data, deadline);
  result.rates = rates.used();
  if (result.outcome == TemporalResult::Outcome::Violated) {
    const model::Connection& rule = *shape->connections[static_cast<size_t>(r)];
    result.explanation = explain(result, p, rule, app.find_rate(rule.source) != nullptr);
  }
  return result;
}

}  // namespace arbc::verify::temporal
