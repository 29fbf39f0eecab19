#include "verify/temporal/bmc.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "verify/temporal/counterexample.h"

namespace arbc::verify::temporal {
namespace {

using Clock = std::chrono::steady_clock;

// Runs `solver` with the time left; z3::unknown (with *reason) when none is left or it gave up.
z3::check_result run(z3::solver& solver, Clock::time_point deadline, std::string* reason) {
  auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  if (left.count() <= 0) {
    *reason = "timeout";
    return z3::unknown;
  }
  try {
    solver.set("timeout", static_cast<unsigned>(std::min<long long>(left.count(), 1u << 30)));
    z3::check_result r = solver.check();
    if (r == z3::unknown) {
      std::string why = solver.reason_unknown();
      *reason =
          why.find("timeout") != std::string::npos || why.find("canceled") != std::string::npos
              ? "timeout"
              : "resource limit (" + why + ")";
    }
    return r;
  } catch (const z3::exception& e) {
    *reason = std::string("solver error: ") + e.msg();
    return z3::unknown;
  }
}

// Whether every step of `n` in model `m` falls on a whole microsecond.
bool on_microsecond_grid(const Unrolling& u, const z3::model& m, int n, z3::context& ctx) {
  for (int k = 0; k < n; ++k) {
    z3::expr us = m.eval(u.time(k) * ctx.real_val(1000000), true);
    // Compared as text: a denominator beyond 64 bits would make get_numeral_int64 throw.
    if (!us.is_numeral() || us.denominator().to_string() != "1") return false;
  }
  return true;
}

// A model of the violation whose steps all fall on whole microseconds, when there is one. A
// tests file writes times to the microsecond (core/time_text.h), so a trace off that grid (a
// step a third of a second in, a hair inside a window's edge) may not replay; the solver is
// asked once more, with the grid and at most 2 s, and the off-grid model stays otherwise.
z3::model prefer_microseconds(z3::solver& solver, const Unrolling& u, int n, z3::model m,
                              z3::context& ctx, Clock::time_point deadline) {
  if (on_microsecond_grid(u, m, n, ctx)) return m;
  solver.push();
  for (int k = 0; k < n; ++k) {
    z3::expr us = ctx.int_const(("us!" + std::to_string(k)).c_str());
    solver.add(u.time(k) * ctx.real_val(1000000) == z3::to_real(us));
  }
  std::string why;
  if (run(solver, std::min(deadline, Clock::now() + std::chrono::seconds(2)), &why) == z3::sat)
    m = solver.get_model();
  solver.pop();
  return m;
}

}  // namespace

std::optional<PropertyShape> property_shape(const model::App& app, const model::TemporalProperty& p,
                                            std::string* err) {
  std::optional<PortShape> shape = port_shape(app, p.port, err);
  if (!shape) return std::nullopt;
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
                              DataQuery* data, Clock::time_point deadline) {
  TemporalResult result;
  result.property = p;
  for (const PortShape::Assumed& a : shape.assumptions) result.assumptions.push_back(a.assumption);
  // One solver for all n: step n is added for good, the violation at n inside a push/pop, so
  // Z3 keeps what it learnt about the first steps (a fresh solver per n redid it every time).
  z3::solver solver(ctx);
  Unrolling u(shape, std::max(0, first - 1), ctx, solver);
  for (int n = first; n <= bound; ++n) {
    u.extend();
    solver.push();
    solver.add(violation(u, n));
    ++result.solver_queries;
    z3::check_result answer = run(solver, deadline, &result.unknown_reason);
    if (answer == z3::unknown) {
      result.outcome = TemporalResult::Outcome::Unknown;
      result.bound = n - 1;
      return result;
    }
    if (answer == z3::sat) {
      z3::model m = prefer_microseconds(solver, u, n, solver.get_model(), ctx, deadline);
      for (int k = 0; k < n; ++k) result.trace.push_back(u.trace_step(m, k));
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
