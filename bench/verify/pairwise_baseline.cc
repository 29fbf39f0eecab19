#include "bench/verify/pairwise_baseline.h"

#include <z3++.h>

#include <map>

#include "verify/port_scope.h"

namespace arbc::verify {
namespace {

z3::expr encode(z3::context& ctx, const Constraint& c) {
  switch (c.op) {
    case Constraint::Op::True:
      return ctx.bool_val(true);
    case Constraint::Op::False:
      return ctx.bool_val(false);
    case Constraint::Op::Event:
      return ctx.bool_const(c.event.c_str());
    case Constraint::Op::Not:
      return !encode(ctx, c.args[0]);
    default: {
      z3::expr_vector args(ctx);
      for (const Constraint& a : c.args) args.push_back(encode(ctx, a));
      return c.op == Constraint::Op::And ? z3::mk_and(args) : z3::mk_or(args);
    }
  }
}

}  // namespace

PairwiseResult pairwise_baseline(const model::App& app) {
  PairwiseResult out;
  for (const model::ArbitratedPort& port : app.arbitrated_ports) {
    std::string error;
    std::optional<PortScope> built = build_port_scope(app, port, &error);
    if (!built) return out;
    const PortScope& scope = *built;
    z3::context ctx;
    z3::solver solver(ctx);
    for (const DomainConstraint& d : scope.domain) solver.add(encode(ctx, d.formula));
    std::vector<z3::expr> guards;
    for (const ScopedRule& r : scope.rules) guards.push_back(encode(ctx, r.effective_guard));
    for (size_t i = 0; i < guards.size(); ++i) {
      for (size_t j = i + 1; j < guards.size(); ++j) {
        solver.push();
        solver.add(guards[i] && guards[j]);
        ++out.queries;
        if (solver.check() == z3::sat) ++out.overlapping_pairs;
        solver.pop();
      }
    }
  }
  out.ok = true;
  return out;
}

}  // namespace arbc::verify
