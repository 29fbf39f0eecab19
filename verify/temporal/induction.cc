#include "verify/temporal/induction.h"

#include <algorithm>
#include <string>

#include "verify/solver_timeout.h"

namespace arbc::verify::temporal {
namespace {

// Z3's answer with the time left (verify::check); unknown when none is left, the solver gives
// up or throws: the induction then proves nothing.
z3::check_result check(z3::solver& solver, SolverTimeout& timeout) {
  std::string unknown;
  return verify::check(solver, timeout, &unknown);
}

}  // namespace

z3::expr Unrolling::delivered_before_start(int c) const {
  if (start_ == Start::Empty) return ctx_.bool_val(false);
  return ctx_.bool_const(("delivered0!" + std::to_string(c)).c_str());
}

z3::expr Unrolling::last_delivery_before_start(int c) const {
  if (start_ == Start::Empty) return ctx_.int_val(0);
  return ctx_.int_const(("last0!" + std::to_string(c)).c_str());
}

// Entry q of any state: free, except what every reachable state satisfies. An activity entry
// is set at each delivery of its rule for the hold and removed only by a `then unset`, so it
// exists (exactly, without one) when the rule has delivered, and expires a hold after the last
// delivery. A fixed-lifetime entry
// never lives forever; an entry without a lifetime always does.
void Unrolling::add_any_start_entry(size_t q) {
  const Entry& e = shape_.entries[q];
  std::string n = "!" + std::to_string(q) + "!start";
  z3::expr has = ctx_.bool_const(("has" + n).c_str());
  z3::expr forever = ctx_.bool_const(("forever" + n).c_str());
  z3::expr expiry = ctx_.int_const(("expiry" + n).c_str());
  if (e.activity) {
    // A `then unset` may have removed it since: then it exists only if the rule delivered.
    z3::expr delivered = delivered_before_start(e.owner);
    solver_.add(e.unset_by.empty() ? has == delivered : z3::implies(has, delivered));
    if (e.lifetime) {
      solver_.add(!forever &&
                  expiry == last_delivery_before_start(e.owner) + nanos_term(ctx_, *e.lifetime));
    } else {
      solver_.add(forever);
    }
  } else if (!e.free_lifetime) {
    solver_.add(z3::implies(has, e.lifetime ? !forever : forever));
  }
  has_[0].push_back(has);
  forever_[0].push_back(forever);
  expiry_[0].push_back(expiry);
}

// What any state says of times: each rule's last delivery, and the set of each fixed-lifetime
// entry, happened no later than the first step (so such an entry expires by t_1 + lifetime).
void Unrolling::constrain_any_start() {
  for (size_t c = 0; c < shape_.connections.size(); ++c) {
    int i = static_cast<int>(c);
    solver_.add(z3::implies(delivered_before_start(i), last_delivery_before_start(i) <= t_[0]));
  }
  for (size_t q = 0; q < shape_.entries.size(); ++q) {
    const Entry& e = shape_.entries[q];
    if (e.activity || e.free_lifetime || !e.lifetime) continue;
    solver_.add(z3::implies(has_[0][q], expiry_[0][q] <= t_[0] + nanos_term(ctx_, *e.lifetime)));
  }
  if (has_own_deliveries()) constrain_own_deliveries_at_start();
}

void try_induction(TemporalResult& result, const PortShape& shape, const ViolationAt& violation,
                   z3::context& ctx, std::chrono::steady_clock::time_point deadline) {
  if (result.outcome != TemporalResult::Outcome::HoldsToBound) return;
  // A `script` rule's Lua is not analysed: it might set any event, which the unrolling's
  // entries do not show; the bounded verdict says as much, a proof would claim too much.
  for (const model::Connection* c : shape.connections)
    if (c->opaque) return;
  z3::solver solver(ctx);
  SolverTimeout timeout(deadline);
  Unrolling u(shape, 0, ctx, solver, Unrolling::Start::AnyState);
  // k <= bound: the base case (no violation from the start within k messages) is the bounded
  // search's, which went to `bound`.
  for (int k = 1; k <= result.bound; ++k) {
    u.extend();
    if (k > 1) solver.add(!violation(u, k - 1));  // the property held at message k-1
    solver.push();
    solver.add(violation(u, k));
    ++result.solver_queries;
    z3::check_result answer = check(solver, timeout);
    solver.pop();
    if (answer == z3::unknown) return;  // no proof: the bounded verdict stands
    if (answer == z3::unsat) {
      std::string first = k == 1 ? "no message" : "no " + std::to_string(k) + " messages";
      std::string held = k == 1 ? "" : " that keep it for the first " + std::to_string(k - 1) + ",";
      result.outcome = TemporalResult::Outcome::Proved;
      result.induction_k = k;
      result.proof = "k-induction with k = " + std::to_string(k) + ": from any state, " + first +
                     " into " + shape.port + held + " violate" + (k == 1 ? "s" : "") +
                     " it at the last";
      return;
    }
  }
}

}  // namespace arbc::verify::temporal
