// Semantic checks of environment assumptions (docs/language.md#environment-assumptions):
// `assume EVENT only after RULE [until RULE2];` and `assume not EVENT for D after RULE;`
// constrain what the feeds report, so EVENT must be one that only feeds set (a status flag or a
// derived event), the two rules must be different rules of one port, the port whose runs the
// model checker unrolls, and D a positive duration.
#include <string>
#include <vector>

#include "compiler/frontend/sema_context.h"

namespace arbc::frontend {

using namespace ast;

void Sema::check_assume(AssumeDecl& a) {
  auto ev = events_.find(a.event);
  if (ev == events_.end()) {
    unknown(a.event_loc, "unknown event '" + a.event + "'", diag::UnknownEvent, a.event,
            event_names_);
  } else if (spec_.event_symbols[ev->second].kind == EventSymbol::Kind::Manual) {
    // An event that monitor code sets belongs to the app: assuming when it is present would
    // assume the app's own behaviour, which is what the checker has to decide.
    error(a.event_loc,
          "'" + a.event + "' is set by monitor code (`event " + a.event +
              ";`), not reported by the environment; an assumption is about an event that a "
              "feed sets: a status flag (`events from M.p { ... }`) or a derived event",
          diag::AssumeEvent);
  }
  if (a.absent_for.expr) check_duration(a.absent_for, "the `for` period");
  a.after_decl = unique_rule(a.after, a.after_loc, "an assumption");
  if (!a.until.empty()) a.until_decl = unique_rule(a.until, a.until_loc, "an assumption");
  if (!a.after_decl || (!a.until.empty() && !a.until_decl) || ev == events_.end()) {
    a.after_decl = nullptr;  // reported: lowering skips it
    return;
  }
  bool bad = false;
  if (a.until_decl == a.after_decl) {
    error(a.until_loc,
          "`assume " + a.event + " only after " + a.after + " until " + a.until +
              "` names one rule twice: name the rule after which " + a.event + " is withdrawn",
          diag::AssumePair);
    bad = true;
  } else if (a.until_decl && a.after_decl->port != a.until_decl->port) {
    error(a.until_loc,
          "'" + a.after + "' goes into " + a.after_decl->port->port.qualified() + " but '" +
              a.until + "' into " + a.until_decl->port->port.qualified() +
              "; an assumption relates two rules of one port (the model checker follows one "
              "port's messages)",
          diag::AssumePair);
    bad = true;
  }
  if (bad || spec_.event_symbols[ev->second].kind == EventSymbol::Kind::Manual ||
      !a.after_decl->port)
    a.after_decl = nullptr;
}

}  // namespace arbc::frontend
