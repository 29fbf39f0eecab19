#include "verify/temporal/spacing.h"

#include <algorithm>
#include <cstdio>

#include "core/time_text.h"
#include "verify/temporal/counterexample.h"
#include "verify/temporal/unrolling.h"

namespace arbc::verify::temporal {
namespace {

using Clock = std::chrono::steady_clock;

// The index of rule `rule` among the shape's connections; -1 when it has none.
int rule_index(const PortShape& shape, const std::string& rule) {
  for (size_t i = 0; i < shape.connections.size(); ++i) {
    const model::Connection& c = *shape.connections[i];
    if (c.kind == model::ConnectionKind::Rule && c.name == rule) return static_cast<int>(i);
  }
  return -1;
}

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

// A throttle on the rule at least the window proves the property for every run: the runtime
// drops a delivery less than the period after the previous one (runtime/message_path.cc), so
// any two are at least the period, hence the window, apart. Empty when it does not apply.
std::string throttle_proof(const model::Connection& c, double window) {
  if (!c.throttle || *c.throttle < window) return "";
  std::string period = time_text(*c.throttle) + "s";
  return "'" + c.name + "' has `throttle " + period +
         ";`, at least the window, and the runtime drops a delivery less than " + period +
         " after the last one";
}

// The last of `n` steps is a delivery of rule r less than `window` after an earlier one.
z3::expr violation(const Unrolling& u, int r, int n, double window, z3::context& ctx) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", window);
  z3::expr w = ctx.real_val(text);
  z3::expr_vector earlier(ctx);
  for (int i = 0; i < n - 1; ++i)
    earlier.push_back(u.delivers(r, i) && u.time(n - 1) - u.time(i) < w);
  return u.delivers(r, n - 1) && z3::mk_or(earlier);
}

}  // namespace

std::optional<TemporalResult> check_spacing(const model::App& app, const model::TemporalProperty& p,
                                            int bound, z3::context& ctx, DataQuery* data,
                                            Clock::time_point deadline, std::string* err) {
  std::optional<PortShape> shape = port_shape(app, p.port, err);
  if (!shape) return std::nullopt;
  int r = rule_index(*shape, p.rule);
  if (r < 0) {
    *err = "the property at line " + std::to_string(p.loc.line) + " names rule '" + p.rule +
           "', which " + p.port + " does not have";
    return std::nullopt;
  }
  TemporalResult result;
  result.property = p;
  // The first n with a violation gives a shortest trace: no shorter one was found before. One
  // solver for all n: step n-1 is added for good, the violation at n inside a push/pop, so Z3
  // keeps what it learnt about the first steps (a fresh solver per n redid it every time).
  z3::solver solver(ctx);
  Unrolling u(*shape, 1, ctx, solver);
  for (int n = 2; n <= bound; ++n) {
    u.extend();
    solver.push();
    solver.add(violation(u, r, n, p.window, ctx));
    ++result.solver_queries;
    z3::check_result answer = run(solver, deadline, &result.unknown_reason);
    if (answer == z3::unknown) {
      result.outcome = TemporalResult::Outcome::Unknown;
      result.bound = n - 1;
      return result;
    }
    if (answer == z3::sat) {
      z3::model m = solver.get_model();
      for (int k = 0; k < n; ++k) result.trace.push_back(u.trace_step(m, k));
      if (data) {
        result.replay_test = counterexample_test(*shape, u, m, n, p, *data, &result.not_replayable);
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
  // The search is kept even where the throttle decides: a violation it found would mean that
  // the model of the throttle and the argument disagree, and the replay would judge it.
  result.proof = throttle_proof(*shape->connections[static_cast<size_t>(r)], p.window);
  if (!result.proof.empty()) result.outcome = TemporalResult::Outcome::Proved;
  return result;
}

}  // namespace arbc::verify::temporal
