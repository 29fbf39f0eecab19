#include "verify/temporal/absence.h"

#include "verify/solver_timeout.h"
#include "verify/temporal/bmc.h"
#include "verify/temporal/constraint_expr.h"
#include "verify/temporal/induction.h"

namespace arbc::verify::temporal {
namespace {

// Why `event` is never present while rule `c` delivers, in every run; empty when no reason
// that needs no bound is known. A delivery needs the rule's constraint true on the decision
// state, and the property reads `event` on that same state: if the constraint and `event` are
// jointly unsatisfiable as a formula over free events (or nothing can set `event` into the
// port), no decision of any run delivers with `event` present.
std::string decision_proof(const PortShape& shape, const model::Connection& c,
                           const std::string& event, z3::context& ctx,
                           std::chrono::steady_clock::time_point deadline) {
  // A `script` rule's Lua is not analysed: it might set any event, so "nothing sets it" needs
  // every connection into the port to be known.
  bool all_known = true;
  for (const model::Connection* into : shape.connections) all_known &= !into->opaque;
  if (all_known && !sets_into(shape, event))
    return "no connection into " + shape.port + " sets " + event +
           ", so it is never present in its container";  // vacuous: check_absence says so
  auto free_event = [&](const std::string& e) { return ctx.bool_const(("ev!" + e).c_str()); };
  z3::solver s(ctx);
  s.add(constraint_expr(c.constraint, ctx, free_event) && free_event(event));
  SolverTimeout timeout(deadline);  // the run's deadline (it was a fixed 10 s)
  std::string unknown;
  if (check(s, timeout, &unknown) != z3::unsat) return "";
  return "'" + c.name + "' is selected only when its constraint `" + c.constraint.to_string() +
         "` holds, which is false whenever " + event + " is present";
}

}  // namespace

std::optional<TemporalResult> check_absence(const model::App& app, const model::TemporalProperty& p,
                                            int bound, z3::context& ctx, DataQuery* data,
                                            std::chrono::steady_clock::time_point deadline,
                                            std::string* err, bool faithful) {
  std::optional<PropertyShape> ps = property_shape(app, p, err, faithful, data);
  if (!ps) return std::nullopt;
  const PortShape* shape = &ps->shape;
  int r = ps->rule;
  auto violation = [&](const Unrolling& u, int n) {
    return u.delivers(r, n - 1) && u.present_at_decision(p.event, n - 1);
  };
  TemporalResult result = bounded_search(*shape, p, 1, bound, violation, ctx, data, deadline);
  if (result.outcome != TemporalResult::Outcome::HoldsToBound) return result;
  // As for spacing, the search runs first: a violation despite the argument would be a bug
  // that the replay exposes.
  result.proof =
      decision_proof(*shape, *shape->connections[static_cast<size_t>(r)], p.event, ctx, deadline);
  if (!result.proof.empty()) result.outcome = TemporalResult::Outcome::Proved;
  bool all_known = true;
  for (const model::Connection* into : shape->connections) all_known &= !into->opaque;
  // True of every run because the event cannot be there: a property that says nothing.
  if (all_known && !sets_into(*shape, p.event)) {
    result.outcome = TemporalResult::Outcome::Vacuous;
    return result;
  }
  try_induction(result, *shape, violation, ctx, deadline);
  return result;
}

}  // namespace arbc::verify::temporal
