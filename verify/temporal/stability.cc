#include "verify/temporal/stability.h"

#include <vector>

#include "verify/temporal/bmc.h"
#include "verify/temporal/rates.h"

namespace arbc::verify::temporal {
namespace {

// Per step k: whether it is a switch (a delivery by a rule other than the last deliverer
// before it). `last` is the index of the last rule to deliver (-1: none yet), one nested
// term per step, which Z3 shares, so the formula grows linearly.
std::vector<z3::expr> switches(const Unrolling& u, const std::vector<int>& rules, int n,
                               z3::context& ctx) {
  std::vector<z3::expr> out;
  z3::expr last = ctx.int_val(-1);
  for (int k = 0; k < n; ++k) {
    z3::expr_vector is(ctx);
    z3::expr next = last;
    for (int c : rules) {
      is.push_back(u.delivers(c, k) && last != -1 && last != c);
      next = z3::ite(u.delivers(c, k), ctx.int_val(c), next);
    }
    out.push_back(z3::mk_or(is));
    last = next;
  }
  return out;
}

// The last of `n` steps is a switch less than `window` after an earlier switch, under the
// rates up to that step.
z3::expr violation(const Unrolling& u, const std::vector<int>& rules, const Rates& rates, int n,
                   Nanos window, z3::context& ctx) {
  z3::expr w = nanos_term(ctx, window);
  std::vector<z3::expr> sw = switches(u, rules, n, ctx);
  z3::expr_vector earlier(ctx);
  for (int j = 0; j < n - 1; ++j) earlier.push_back(sw[j] && u.time(n - 1) - u.time(j) < w);
  return sw[n - 1] && z3::mk_or(earlier) &&
         rates.up_to(u, n, u.time(n - 1), Rates::Horizon::After) && rates.accepting(u, n);
}

}  // namespace

std::optional<TemporalResult> check_stability(const model::App& app,
                                              const model::TemporalProperty& p, int bound,
                                              z3::context& ctx, DataQuery* data,
                                              std::chrono::steady_clock::time_point deadline,
                                              std::string* err, bool faithful) {
  std::optional<PropertyShape> ps = property_shape(app, p, err, faithful, data);
  if (!ps) return std::nullopt;
  const PortShape* shape = &ps->shape;
  std::vector<int> rules;
  for (size_t c = 0; c < shape->connections.size(); ++c)
    if (shape->connections[c]->kind == model::ConnectionKind::Rule)
      rules.push_back(static_cast<int>(c));
  Rates rates(app, *shape, ctx);
  TemporalResult result = bounded_search(
      *shape, p, 3, bound,
      [&](const Unrolling& u, int n) { return violation(u, rules, rates, n, p.window, ctx); }, ctx,
      data, deadline);
  result.rates = rates.used();
  if (result.outcome == TemporalResult::Outcome::HoldsToBound)
    result.rated_span = rates.span(result.bound);
  return result;
}

}  // namespace arbc::verify::temporal
