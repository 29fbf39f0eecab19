// The e-stop trap of issue 42 (docs/language.md#a-stop-that-must-act-at-once): a derived event with
// `for D` whose predicate says a stop flag is off (`event e_ok = EStop.engaged : not engaged
// for 200ms;`), read positively by a rule (`nav: ... when e_ok`). A message on which the
// predicate is false does not clear such an event, it lapses D after the last message that
// set it, so the rule keeps delivering for up to D after the stop: a warning, with the fix.
#pragma once

#include <vector>

#include "compiler/frontend/ast.h"
#include "core/diagnostic.h"

namespace arbc::frontend {

// One warning per such event and port whose rules read it positively. Reads sema's fields.
void warn_lapsing_permissions(const ast::Spec& spec, std::vector<Diagnostic>& out);

}  // namespace arbc::frontend
