#include "verify/temporal/spacing.h"

#include "core/duration_literal.h"
#include "core/time_text.h"
#include "verify/temporal/bmc.h"
#include "verify/temporal/induction.h"
#include "verify/temporal/unrolling.h"

namespace arbc::verify::temporal {
namespace {

// A throttle on the rule at least the window proves the property for every run: the runtime
// drops a delivery less than the period after the previous one (runtime/message_path.cc), so
// any two are at least the period, hence the window, apart. Empty when it does not apply.
std::string throttle_proof(const model::Connection& c, Nanos window) {
  if (!c.throttle || *c.throttle < window) return "";
  std::string period = duration_literal(*c.throttle);
  return "'" + c.name + "' has `throttle " + period +
         ";`, at least the window, and the runtime drops a delivery less than " + period +
         " after the last one";
}

// The last of `n` steps is a delivery of rule r less than `window` after an earlier delivery
// of rule `first` (r itself for `never two r within W`).
z3::expr violation(const Unrolling& u, int first, int r, int n, Nanos window, z3::context& ctx) {
  z3::expr w = nanos_term(ctx, window);
  z3::expr_vector earlier(ctx);
  for (int i = 0; i < n - 1; ++i)
    earlier.push_back(u.delivers(first, i) && u.time(n - 1) - u.time(i) < w);
  // The first rule's last delivery before the first step (k-induction's any state; none from
  // the start).
  if (u.from_any_state())
    earlier.push_back(u.delivered_before_start(first) &&
                      u.time(n - 1) - u.last_delivery_before_start(first) < w);
  return u.delivers(r, n - 1) && z3::mk_or(earlier);
}

}  // namespace

std::optional<TemporalResult> check_spacing(const model::App& app, const model::TemporalProperty& p,
                                            int bound, z3::context& ctx, DataQuery* data,
                                            std::chrono::steady_clock::time_point deadline,
                                            std::string* err, bool faithful) {
  std::optional<PropertyShape> ps = property_shape(app, p, err, faithful, data);
  if (!ps) return std::nullopt;
  const PortShape* shape = &ps->shape;
  int r = ps->rule;
  int first = ps->other < 0 ? r : ps->other;  // `never two r within W` spaces r from itself
  ViolationAt at = [&](const Unrolling& u, int n) {
    return violation(u, first, r, n, p.window, ctx);
  };
  TemporalResult result = bounded_search(*shape, p, 2, bound, at, ctx, data, deadline);
  if (result.outcome != TemporalResult::Outcome::HoldsToBound) return result;
  // The search is kept even where the throttle decides: a violation it found would mean that
  // the model of the throttle and the argument disagree, and the replay would judge it. A
  // throttle spaces a rule from itself only.
  if (first == r)
    result.proof = throttle_proof(*shape->connections[static_cast<size_t>(r)], p.window);
  if (!result.proof.empty()) result.outcome = TemporalResult::Outcome::Proved;
  try_induction(result, *shape, at, ctx, deadline);
  return result;
}

}  // namespace arbc::verify::temporal
