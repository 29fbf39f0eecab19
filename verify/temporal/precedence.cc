#include "verify/temporal/precedence.h"

#include "verify/temporal/bmc.h"

namespace arbc::verify::temporal {
namespace {

// The last of `n` steps is a delivery of rule a while a is not "armed": armed after a step
// that b delivered, disarmed by a delivery of a (one connection runs per step, so never both).
// Built as one nested term, which Z3 shares, so it grows linearly with n.
z3::expr violation(const Unrolling& u, int a, int b, int n, z3::context& ctx) {
  z3::expr armed = ctx.bool_val(false);
  for (int i = 0; i < n - 1; ++i) armed = u.delivers(b, i) || (armed && !u.delivers(a, i));
  return u.delivers(a, n - 1) && !armed;
}

}  // namespace

std::optional<TemporalResult> check_precedence(const model::App& app,
                                               const model::TemporalProperty& p, int bound,
                                               z3::context& ctx, DataQuery* data,
                                               std::chrono::steady_clock::time_point deadline,
                                               std::string* err) {
  std::optional<PortShape> shape = port_shape(app, p.port, err);
  if (!shape) return std::nullopt;
  int a = property_rule(*shape, p, p.rule, err);
  if (a < 0) return std::nullopt;
  int b = property_rule(*shape, p, p.other, err);
  if (b < 0) return std::nullopt;
  return bounded_search(
      *shape, p, 1, bound, [&](const Unrolling& u, int n) { return violation(u, a, b, n, ctx); },
      ctx, data, deadline);
}

}  // namespace arbc::verify::temporal
