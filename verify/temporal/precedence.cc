#include "verify/temporal/precedence.h"

#include "verify/temporal/bmc.h"
#include "verify/temporal/induction.h"

namespace arbc::verify::temporal {
namespace {

// The last of `n` steps is a delivery of rule a while a is not "armed": armed after a step
// that b delivered, disarmed by a delivery of a (one connection runs per step, so never both).
// The monitor is the unrolling's (Unrolling::armed_before), so an assumption that follows the
// same two rules shares its state in k-induction's step case.
z3::expr violation(const Unrolling& u, int a, int b, int n) {
  return u.delivers(a, n - 1) && !u.armed_before(b, a, n - 1);
}

}  // namespace

std::optional<TemporalResult> check_precedence(const model::App& app,
                                               const model::TemporalProperty& p, int bound,
                                               z3::context& ctx, DataQuery* data,
                                               std::chrono::steady_clock::time_point deadline,
                                               std::string* err, bool faithful) {
  std::optional<PropertyShape> ps = property_shape(app, p, err, faithful, data);
  if (!ps) return std::nullopt;
  const PortShape* shape = &ps->shape;
  int a = ps->rule, b = ps->other;
  ViolationAt at = [&](const Unrolling& u, int n) { return violation(u, a, b, n); };
  TemporalResult result = bounded_search(*shape, p, 1, bound, at, ctx, data, deadline);
  try_induction(result, *shape, at, ctx, deadline);
  return result;
}

}  // namespace arbc::verify::temporal
