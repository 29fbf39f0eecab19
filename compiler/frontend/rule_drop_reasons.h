// Whether a rule's generated monitor can ever drop a message for a given reason, so that a test
// expecting `RULE drops "rejected"` of a rule without `accept` is refused before it runs: such a
// test can never pass, and the likelier intent ("not-selected", by the `when`) is said instead.
#pragma once

#include <string>

#include "compiler/frontend/ast.h"

namespace arbc::frontend {

// "" when `rule` can drop a message for `reason`, else why it cannot ("it has no `accept`").
// Only the reasons that depend on the rule's own body are judged (rejected, throttled); a
// `script` rule can give any reason.
std::string why_rule_never_drops(const ast::Rule& rule, const std::string& reason);

}  // namespace arbc::frontend
