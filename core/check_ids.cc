#include "core/check_ids.h"

namespace arbc::frontend {

namespace {

constexpr CheckId kIds[] = {
    {"arity", "a builtin called with the wrong number of arguments"},
    {"assign", "an assignment to something that is not a `var`"},
    {"bad-character", "a character that cannot start any token"},
    {"bad-escape", "an unknown escape sequence in a string literal"},
    {"bad-number", "a number glued to letters that are not a duration unit"},
    {"bad-type", "a malformed type (unknown type arguments, `list` without an element)"},
    {"connect-into-arbitrated", "a `connect` into a port that has an `arbitrate` block"},
    {"constraint-term", "a constraint mentions something other than events, true, false"},
    {"duplicate", "a name defined twice in the same scope"},
    {"duration", "a duration position holds something that is not a positive duration"},
    {"emit-type", "a delivered value's type differs from the destination port's type"},
    {"empty-spec", "the file declares nothing"},
    {"event-in-expression", "an event read in a value expression"},
    {"fan-in", "two sources into a port that is not arbitrated"},
    {"hold-missing", "a rule of a `by priority` port other than the lowest has no `hold`"},
    {"hold-on-lowest", "the lowest rule of a `by priority` port has a `hold`"},
    {"hold-without-priority", "`hold` on a rule of a port that is not `by priority`"},
    {"invalid-utf8", "the file is not valid UTF-8"},
    {"io", "the file cannot be read (missing, a directory, unreadable)"},
    {"lambda", "a lambda outside the function argument of min_by / max_by"},
    {"missing-app", "the spec has no `app NAME;` declaration"},
    {"nesting-too-deep", "brackets, operators or else-if chains nested deeper than the limit"},
    {"not-arbitrated", "an `assert` on a port that has no `arbitrate` block"},
    {"not-constant", "a `const` whose value is not a constant expression"},
    {"otherwise", "`otherwise` not as a whole rule constraint, or twice in one port"},
    {"port-direction", "an `in` port used as a source or an `out` port as a destination"},
    {"predicate-type", "a derived event's predicate is not bool"},
    {"script-alone", "a body with `script` that contains other statements"},
    {"script-missing", "a `script` file that does not exist beside the spec"},
    {"set-fed-event", "monitor code sets or unsets an event fed from a stream"},
    {"statement-context", "a statement where it cannot run (emit in `every`, nested `every`)"},
    {"status-source-type", "an `events from` source port that is not list<string>"},
    {"syntax", "the text does not follow the grammar"},
    {"type-cycle", "a named type defined in terms of itself"},
    {"type-mismatch", "an operand, condition or value of the wrong type"},
    {"unknown-event", "an event name that is not declared"},
    {"unknown-field", "a field that the record type does not have"},
    {"unknown-function", "a call of something that is not a builtin"},
    {"unknown-module", "a module name that is not declared"},
    {"unknown-name", "a name in an expression that is not declared"},
    {"unknown-port", "a port that the module does not have"},
    {"unknown-rule", "an `assert` names a rule the port does not have"},
    {"unknown-type", "a type name that is not declared"},
    {"unterminated-comment", "a `/*` comment without its `*/`"},
    {"unterminated-string", "a string literal without its closing quote"},
    // `arbc verify APP.xml` and `arbc import yarp` (docs/yarp.md#diagnostics; golden cases in
    // tests/yarp_verify/).
    {"yarp-carrier", "a carrier string YARP reads differently, or a monitor arbc cannot read"},
    {"yarp-constraint-syntax", "a monitor's constraint that does not parse"},
    {"yarp-event-forever", "an event set without a lifetime that its monitor never unsets"},
    {"yarp-keyword-event", "an event name that is, or is part of, and/or/not/true/false"},
    {"yarp-monitor-missing", "the Lua file a carrier names is not found"},
    {"yarp-opaque", "a monitor whose event names arbc cannot all know"},
    {"yarp-script-error", "a monitor that fails to load, or whose create fails"},
    {"yarp-shared-event", "an event set or read by monitors on different ports"},
    {"yarp-substring-event", "an event name YARP also replaces inside another name"},
    {"yarp-trig-interval", "PortMonitor.setTrigInterval, whose period YARP multiplies by 1000"},
    {"yarp-xml", "a yarpmanager XML that cannot be read, or parts of it arbc does not read"},
};

}  // namespace

std::span<const CheckId> all_check_ids() { return kIds; }

}  // namespace arbc::frontend
