#include "verify/temporal/bmc.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "verify/solver_timeout.h"
#include "verify/temporal/counterexample.h"

namespace arbc::verify::temporal {
namespace {

using Clock = std::chrono::steady_clock;

// Runs `solver` with the time left; z3::unknown (with *reason) when none is left or it gave up
// (verify::check, the one wrapper for Z3 calls).
z3::check_result run(z3::solver& solver, SolverTimeout& timeout, std::string* reason) {
  return check(solver, timeout, reason);
}

// Whether every step of `n` in model `m` falls on a multiple of 1/`per_second` seconds.
bool on_grid(const Unrolling& u, const z3::model& m, int n, int per_second, z3::context& ctx) {
  for (int k = 0; k < n; ++k) {
    z3::expr ticks = m.eval(u.time(k) * ctx.real_val(per_second), true);
    // Compared as text: a denominator beyond 64 bits would make get_numeral_int64 throw.
    if (!ticks.is_numeral() || ticks.denominator().to_string() != "1") return false;
  }
  return true;
}

// Step k at a multiple of 1/`per_second` seconds.
z3::expr grid_step(const Unrolling& u, int k, int per_second, z3::context& ctx) {
  z3::expr ticks =
      ctx.int_const(("ticks!" + std::to_string(per_second) + "!" + std::to_string(k)).c_str());
  return u.time(k) * ctx.real_val(per_second) == z3::to_real(ticks);
}

// Asks `solver` again with every one of the `n` steps on the grid of 1/`per_second` seconds:
// sat (with *m its model), unsat, or unknown when `timeout` runs out.
z3::check_result ask_on_grid(z3::solver& solver, const Unrolling& u, int n, int per_second,
                             z3::context& ctx, SolverTimeout& timeout, z3::model* m) {
  solver.push();
  for (int k = 0; k < n; ++k) solver.add(grid_step(u, k, per_second, ctx));
  std::string why;
  z3::check_result answer = run(solver, timeout, &why);
  if (answer == z3::sat) *m = solver.get_model();
  solver.pop();
  return answer;
}

constexpr int kNanosPerSecond = 1000000000;

// The model of a violation over real times, moved onto the instants the runtime has: whole
// nanoseconds (core/instant.h). A violation with no model there (two steps strictly between
// instants a nanosecond apart) is none the runtime can produce: nullopt. Where it can, the
// steps go on a readable grid too, multiples of 50 ms, else 1 ms, else 1 us (at most 2 s of
// asking in all), so that the tests file reads well; the model stays when the solver cannot
// say in time, and its replay decides.
std::optional<z3::model> on_runtime_grid(z3::solver& solver, const Unrolling& u, int n, z3::model m,
                                         z3::context& ctx, Clock::time_point deadline) {
  SolverTimeout at_most(std::min(deadline, Clock::now() + std::chrono::seconds(2)));
  for (int per_second : {20, 1000, 1000000}) {
    if (on_grid(u, m, n, per_second, ctx)) return m;
    if (ask_on_grid(solver, u, n, per_second, ctx, at_most, &m) == z3::sat) return m;
  }
  if (on_grid(u, m, n, kNanosPerSecond, ctx)) return m;
  SolverTimeout until_deadline(deadline);
  z3::check_result answer = ask_on_grid(solver, u, n, kNanosPerSecond, ctx, until_deadline, &m);
  if (answer == z3::unsat) return std::nullopt;
  return m;
}

}  // namespace

std::optional<PropertyShape> property_shape(const model::App& app, const model::TemporalProperty& p,
                                            std::string* err, bool faithful) {
  std::optional<PortShape> shape = port_shape(app, p.port, err);
  if (!shape) return std::nullopt;
  shape->faithful = faithful;
  PropertyShape ps{std::move(*shape)};
  for (auto [name, index] : {std::pair{&p.rule, &ps.rule}, std::pair{&p.other, &ps.other}}) {
    if (name->empty()) continue;
    *index = rule_index(ps.shape, *name);
    if (*index < 0) {
      *err = "the property at line " + std::to_string(p.loc.line) + " names rule '" + *name +
             "', which " + p.port + " does not have";
      return std::nullopt;
    }
  }
  return ps;
}

TemporalResult bounded_search(const PortShape& shape, const model::TemporalProperty& p, int first,
                              int bound, const ViolationAt& violation, z3::context& ctx,
                              DataQuery* data, Clock::time_point deadline, const Witness& witness) {
  TemporalResult result;
  result.property = p;
  for (const PortShape::Assumed& a : shape.assumptions) result.assumptions.push_back(a.assumption);
  // One solver for all n: step n is added for good, the violation at n inside a push/pop, so
  // Z3 keeps what it learnt about the first steps (a fresh solver per n redid it every time).
  z3::solver solver(ctx);
  SolverTimeout timeout(deadline);
  Unrolling u(shape, std::max(0, first - 1), ctx, solver);
  // Once a violation over real times had no model on the runtime's nanoseconds, every step
  // stays on them: the search is then about the runs the runtime has.
  bool whole_nanos = false;
  for (int n = first; n <= bound; ++n) {
    u.extend();
    if (whole_nanos) solver.add(grid_step(u, n - 1, kNanosPerSecond, ctx));
    solver.push();
    solver.add(violation(u, n));
    ++result.solver_queries;
    z3::check_result answer = run(solver, timeout, &result.unknown_reason);
    if (answer == z3::unknown) {
      result.outcome = TemporalResult::Outcome::Unknown;
      result.bound = n - 1;
      return result;
    }
    if (answer == z3::sat) {
      std::optional<z3::model> grid =
          on_runtime_grid(solver, u, n, solver.get_model(), ctx, deadline);
      if (!grid) {
        solver.pop();
        for (int k = 0; k < n && !whole_nanos; ++k)
          solver.add(grid_step(u, k, kNanosPerSecond, ctx));
        whole_nanos = true;
        continue;
      }
      const z3::model& m = *grid;
      for (int k = 0; k < n; ++k) result.trace.push_back(u.trace_step(m, k));
      if (witness) witness(m, n);
      if (data) {
        result.replay_test = counterexample_test(shape, u, m, n, p, *data, &result.not_replayable);
      } else {
        result.not_replayable = "no message data to replay with";
      }
      result.outcome = TemporalResult::Outcome::Violated;
      result.bound = n;
      return result;
    }
    solver.pop();
  }
  result.outcome = TemporalResult::Outcome::HoldsToBound;
  result.bound = bound;
  return result;
}

}  // namespace arbc::verify::temporal
