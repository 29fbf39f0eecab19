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

// Whether every step of `n` in model `m` falls on a multiple of `grid` nanoseconds.
bool on_grid(const Unrolling& u, const z3::model& m, int n, int64_t grid) {
  for (int k = 0; k < n; ++k)
    if (u.time_value(m, k).count() % grid != 0) return false;
  return true;
}

// A model of the violation whose steps fall on a readable grid, when there is one: multiples
// of 50 ms, else of 1 ms, else of 1 us. Every model is on the runtime's instants already (the
// unrolling counts whole nanoseconds), but a trace at 0.333333334 s reads badly in a tests
// file. The solver is asked again per grid, with at most 2 s in all; the first model stays
// when none answers.
z3::model prefer_readable_times(z3::solver& solver, const Unrolling& u, int n, z3::model m,
                                z3::context& ctx, Clock::time_point deadline) {
  SolverTimeout at_most(std::min(deadline, Clock::now() + std::chrono::seconds(2)));
  for (int64_t grid : {50'000'000, 1'000'000, 1'000}) {
    if (on_grid(u, m, n, grid)) return m;
    solver.push();
    for (int k = 0; k < n; ++k) solver.add(z3::mod(u.time(k), ctx.int_val(grid)) == 0);
    std::string why;
    bool found = run(solver, at_most, &why) == z3::sat;
    if (found) m = solver.get_model();
    solver.pop();
    if (found) return m;
  }
  return m;
}

}  // namespace

std::optional<PropertyShape> property_shape(const model::App& app, const model::TemporalProperty& p,
                                            std::string* err, bool faithful, DataQuery* data) {
  std::optional<PortShape> shape = port_shape(app, p.port, err, data);
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
  for (int n = first; n <= bound; ++n) {
    u.extend();
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
      z3::model m = prefer_readable_times(solver, u, n, solver.get_model(), ctx, deadline);
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
