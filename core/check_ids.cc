#include "core/check_ids.h"

namespace arbc::frontend {

namespace {

constexpr std::string_view kCheck = "check";
constexpr std::string_view kVerify = "verify";
constexpr std::string_view kYarp = "yarp";
constexpr std::string_view kInternal = "internal";

constexpr CheckId kIds[] = {
    {"app-json", kVerify, "an app.json that does not load, or whose model is inconsistent"},
    {"arity", kCheck, "a builtin called with the wrong number of arguments"},
    {"assert", kVerify, "a rule can deliver while its asserted property is false"},
    {"assign", kCheck, "an assignment to something that is not a `var`"},
    {"assume-event", kCheck,
     "an assumption about an event that monitor code sets (only feeds' events can be assumed)"},
    {"assume-pair", kCheck,
     "`assume EVENT only after RULE until OTHER` names one rule twice, or rules of two ports"},
    {"bad-character", kCheck, "a character that cannot start any token"},
    {"bad-escape", kCheck, "an unknown escape sequence in a string literal"},
    {"bad-number", kCheck, "a number glued to letters that are not a duration unit"},
    {"bad-type", kCheck, "a malformed type (unknown type arguments, `list` without an element)"},
    {"codegen", kInternal, "a generated monitor does not compile as Lua: a bug in arbc"},
    {"complete", kVerify, "on a `complete` port, some state selects no rule"},
    {"connect-into-arbitrated", kCheck, "a `connect` into a port that has an `arbitrate` block"},
    {"constraint-term", kCheck, "a constraint mentions something other than events, true, false"},
    {"dead", kVerify, "a rule can never be selected (warning; an error with --strict)"},
    {"division-by-zero", kCheck, "`/` or `%` by a constant zero"},
    {"duplicate", kCheck, "a name defined twice in the same scope"},
    {"duration", kCheck, "a duration position holds something that is not a positive duration"},
    {"emit-type", kCheck, "a delivered value's type differs from the destination port's type"},
    {"empty-spec", kCheck, "the file declares nothing"},
    {"event-in-expression", kCheck, "an event read in a value expression"},
    {"exclusive", kVerify, "two rules of one arbitrated port can be selected in the same state"},
    {"fail-open", kCheck,
     "`otherwise WORD after D` on a feed, with a word other than `absent` (the only one a feed's "
     "silence can mean)"},
    {"fan-in", kCheck, "two sources into a port that is not arbitrated"},
    {"hold-missing", kCheck, "a rule of a `by priority` port other than the lowest has no `hold`"},
    {"hold-on-lowest", kCheck, "the lowest rule of a `by priority` port has a `hold`"},
    {"hold-without-priority", kCheck, "`hold` on a rule of a port that is not `by priority`"},
    {"int-overflow", kCheck,
     "a constant int expression, or an int literal, outside the 64-bit range (a monitor would "
     "wrap it)"},
    {"internal", kInternal, "Z3 and the runtime's constraint evaluator disagree: a bug in arbc"},
    {"invalid-utf8", kCheck, "the file is not valid UTF-8"},
    {"io", kCheck, "the file cannot be read (missing, a directory, unreadable)"},
    {"lambda", kCheck, "a lambda outside the function argument of min_by / max_by"},
    {"line-endings", kCheck,
     "a line ends in a carriage return alone (old Mac OS line endings), which arbc does not read "
     "as a line end"},
    {"missing-app", kCheck, "the spec has no `app NAME;` declaration"},
    {"nesting-too-deep", kCheck,
     "brackets, operators or else-if chains nested deeper than the limit"},
    {"not-arbitrated", kCheck, "an `assert` on a port that has no `arbitrate` block"},
    {"not-constant", kCheck, "a `const` whose value is not a constant expression"},
    {"otherwise", kCheck, "`otherwise` not as a whole rule constraint, or twice in one port"},
    {"ownership", kVerify, "a monitor unsets an event it never sets"},
    {"port-direction", kCheck, "an `in` port used as a source or an `out` port as a destination"},
    {"predicate-type", kCheck,
     "a derived event's predicate, a resource's `when` or an assert over `emitted` is not bool"},
    {"priority", kCheck,
     "a declared event takes the name of a `by priority` activity event (act_<rule>), or a "
     "`by priority` port has more rules than can be checked (1,000)"},
    {"resource", kVerify,
     "two ports of a `resource` can each receive a command that uses it, from one message or "
     "two"},
    {"temporal", kVerify,
     "a property over time (`never two RULE within D`, `never RULE while EVENT`, `only RULE after "
     "OTHER`, `after OTHER, RULE within D`) is violated by a timed trace the runtime replays"},
    {"temporal-bound", kVerify,
     "a response's window cannot close within --temporal-bound messages at the given rates "
     "(warning; an error with --strict)"},
    {"list-bound", kVerify,
     "a rule accepts no message whose lists have at most --list-bound elements, so the proof "
     "does not see what it accepts (warning; an error with --strict)"},
    {"vacuous", kVerify,
     "a property over time reads an event nothing can put into its port's container, so it says "
     "nothing (warning; an error with --strict)"},
    {"rate-source", kCheck,
     "a rate (`given M.p every D`) for a source that no rule, stream event or connect reads"},
    {"resource-port", kCheck,
     "a `resource` lists a port that is not arbitrated, a port twice, or fewer than two ports"},
    {"resource-type", kCheck, "the ports of a `resource` have different types"},
    {"script", kCheck, "a `script` file that cannot be read or does not compile as Lua"},
    {"script-alone", kCheck, "a body with `script` that contains other statements"},
    {"script-missing", kCheck, "a `script` file that does not exist beside the spec"},
    {"set-fed-event", kCheck, "monitor code sets or unsets an event fed from a stream"},
    {"statement-context", kCheck,
     "a statement where it cannot run (emit in `every`, nested `every`)"},
    {"status-source-type", kCheck, "an `events from` source port that is not list<string>"},
    {"syntax", kCheck, "the text does not follow the grammar"},
    {"temporal-pair", kCheck,
     "`only RULE after OTHER` or `after OTHER, RULE within D` names one rule twice, or rules of "
     "two different ports"},
    {"temporal-rule", kCheck, "a property over time names a rule used by several ports"},
    {"test-claim", kCheck,
     "`expect exclusive` of a `by priority` port: a claim the app does not make"},
    {"test-expect", kCheck, "a test without an `expect`: it would pass whatever the app does"},
    {"test-port", kCheck,
     "a test names a port or rule it cannot use (an `on RULE` test off that rule's ports)"},
    {"test-reason", kCheck,
     "`expect RULE drops \"reason\"` with an unknown drop reason, or one the rule never gives "
     "(`rejected` without `accept`)"},
    {"test-value", kCheck, "a test's message literal is not a constant value of its port's type"},
    {"test-window", kCheck,
     "a test window that ends before it starts, an event state without `at`, or a `receives` "
     "within a `receives nothing` window of the same port"},
    {"tests-file", kCheck,
     "a tests file (`tests for`) that declares more than tests, or whose app cannot be read"},
    {"type-cycle", kCheck, "a named type defined in terms of itself"},
    {"type-mismatch", kCheck, "an operand, condition or value of the wrong type"},
    {"unfed", kVerify, "a constraint or assert reads an event nothing sets into the port"},
    {"unknown", kVerify, "the solver could not decide a check (timeout, resource limit)"},
    {"unknown-event", kCheck, "an event name that is not declared"},
    {"unknown-field", kCheck, "a field that the record type does not have"},
    {"unknown-function", kCheck, "a call of something that is not a builtin"},
    {"unknown-module", kCheck, "a module name that is not declared"},
    {"unknown-name", kCheck, "a name in an expression that is not declared"},
    {"unknown-port", kCheck, "a port that the module does not have"},
    {"unknown-rule", kCheck,
     "an `assert` or a property over time names a rule that does not exist"},
    {"unknown-type", kCheck, "a type name that is not declared"},
    {"unterminated-comment", kCheck, "a `/*` comment without its `*/`"},
    {"unterminated-string", kCheck, "a string literal without its closing quote"},
    {"unused", kVerify, "an event is set but nothing reads it (warning; an error with --strict)"},
    // `arbc verify APP.xml` and `arbc import yarp` (docs/yarp.md#diagnostics; golden cases in
    // tests/yarp_verify/).
    {"yarp-carrier", kYarp,
     "a carrier string YARP reads differently, or a monitor arbc cannot read"},
    {"yarp-constraint-syntax", kYarp, "a monitor's constraint that does not parse"},
    {"yarp-duplicate-id", kYarp,
     "a connection id used again for another connection into the same port (renamed)"},
    {"yarp-event-forever", kYarp, "an event set without a lifetime that its monitor never unsets"},
    {"yarp-keyword-event", kYarp, "an event name that is, or is part of, and/or/not/true/false"},
    {"yarp-monitor-missing", kYarp, "the Lua file a carrier names is not found"},
    {"yarp-opaque", kYarp, "a monitor whose event names arbc cannot all know"},
    {"yarp-port-name", kYarp, "a <from> or <to> port name that is probably misspelt"},
    {"yarp-require", kYarp,
     "a monitor that does not require(\"yarp\") when it loads: YARP crashes the receiving "
     "process"},
    {"yarp-script-error", kYarp, "a monitor that fails to load, or whose create fails"},
    {"yarp-shared-event", kYarp, "an event set or read by monitors on different ports"},
    {"yarp-spec-name", kYarp,
     "`arbc import yarp`: two YARP modules, ports or connection ids that become one spec name "
     "(renamed)"},
    {"yarp-substring-event", kYarp, "an event name YARP also replaces inside another name"},
    {"yarp-trig-interval", kYarp,
     "PortMonitor.setTrigInterval, whose period YARP multiplies by 1000"},
    {"yarp-xml", kYarp, "a yarpmanager XML that cannot be read, or parts of it arbc does not read"},
};

}  // namespace

std::span<const CheckId> all_check_ids() { return kIds; }

}  // namespace arbc::frontend
