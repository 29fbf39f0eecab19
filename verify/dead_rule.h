// The `dead` findings of one port (docs/checks.md#dead): a rule whose effective guard cannot
// hold, said with its cause when the rule's own body is it, and a port none of whose rules can
// ever be selected.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "verify/port_scope.h"
#include "verify/report.h"

namespace arbc::verify {

// A rule that can never be selected. `under_domain`: the port has invariants or exclusive
// groups (the message says the guard is unsatisfiable under them). A rule whose `when` excludes
// an event its own body sets (or requires one it unsets) gets that cause and the way out.
Finding dead_rule_finding(const ScopedRule& r, const std::string& port, bool under_domain,
                          bool strict);

// The events rule r's body forces against its own `when`, as "sets e_busy" / "unsets e_ok":
// a top-level conjunct `not e` of its constraint with e set on every accepting path, or `e`
// with e unset on every one.
std::vector<std::string> self_excluded(const ScopedRule& r);

// Every delivering rule of `port` is dead (`dead` holds the names, in order, of those found;
// feeds, `when false` rules that only set events, are left out of both): the port never
// receives anything. nullopt when some rule can deliver, or the port has fewer than two (one
// rule's own warning says it all).
std::optional<Finding> dead_port_finding(const PortScope& scope,
                                         const std::vector<std::string>& dead,
                                         size_t delivering_rules, bool strict);

}  // namespace arbc::verify
