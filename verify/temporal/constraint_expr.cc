#include "verify/temporal/constraint_expr.h"

namespace arbc::verify::temporal {

z3::expr constraint_expr(const Constraint& c, z3::context& ctx,
                         const std::function<z3::expr(const std::string&)>& present) {
  switch (c.op) {
    case Constraint::Op::True:
      return ctx.bool_val(true);
    case Constraint::Op::False:
      return ctx.bool_val(false);
    case Constraint::Op::Event:
      return present(c.event);
    case Constraint::Op::Not:
      return !constraint_expr(c.args[0], ctx, present);
    case Constraint::Op::And:
    case Constraint::Op::Or: {
      z3::expr_vector args(ctx);
      for (const Constraint& a : c.args) args.push_back(constraint_expr(a, ctx, present));
      return c.op == Constraint::Op::And ? z3::mk_and(args) : z3::mk_or(args);
    }
  }
  return ctx.bool_val(false);
}

}  // namespace arbc::verify::temporal
