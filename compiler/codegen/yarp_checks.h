// The runtime checks a YARP monitor carries (issue 39, docs/yarp.md#runtime-checks): what a
// monitor can check of what the proof claims or assumes, and what it cannot. A YARP monitor sees
// its own connection's messages and may set events, but YARP's Lua API cannot read a port's
// events (PortMonitor has setEvent, unsetEvent, setConstraint, getConstraint, setTrigInterval
// only) and the monitors of one port share no state. So the rule's own monitor checks:
//   - each assert over `emitted` of the rule, on the value it delivers (the predicate generated
//     from the IR the proof encodes, as claims.lua is for the embedded runtime);
//   - the list bound a bounded proof assumed of the rule's messages: a longer list is dropped,
//     as the embedded runtime drops it (`bad-value`);
//   - each `never two RULE within D` of the rule itself, at each of its deliveries;
//   - `given M.p every D` of the rule's source (in the first rule of that source), at each
//     message M.p sends.
// Each is said on the receiving process's stderr the first time, and counted when the
// connection goes. Exclusivity, asserts over events, resources, the other properties over time
// and the other assumptions (`exclusive`, `invariant`, `assume`, a `given` of a source no rule
// reads) need the port's events or several connections at once: yarp_unchecked() lists them,
// and `arbc build --target yarp` says so.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"

namespace arbc::codegen {

// The spacings of `rule` alone (`never two RULE within D`) that its monitor checks at each of its
// deliveries.
std::vector<const model::TemporalProperty*> yarp_checked_spacings(const model::App& app,
                                                                  const model::Connection& rule);

// The rates (`given M.p every D`) of `rule`'s source that its monitor checks at each message:
// those of the first rule of each source (one report per breach); none for the others.
std::vector<const model::SourceRate*> yarp_checked_rates(const model::App& app,
                                                         const model::Connection& rule);

// The asserts over `emitted` of `rule` that its monitor checks, in the spec's order.
std::vector<const model::Assertion*> yarp_checked_asserts(const model::App& app,
                                                          const model::Connection& rule);

// The Lua of delivering rule `rule`'s checks for its monitor, whose reports name it `who`
// (messages read with the monitor's arbc_in_type): defines arbc_over_bound(msg) when the rule
// has a list bound, arbc_check_claims(value, bottle) when it has asserts over `emitted`, and
// arbc_checks_destroy(); "" when the rule has neither.
std::string yarp_checks_lua(const model::App& app, const model::Connection& rule,
                            const std::string& who);

// The claims and assumptions of `app` no YARP monitor checks, one phrase per kind with its count
// ("exclusivity of 2 ports"); empty when every one is checked.
std::vector<std::string> yarp_unchecked(const model::App& app);

// The checks the YARP monitors of `app` carry, one phrase per kind with its count ("2 list
// bounds", "1 source rate"); empty when they carry none.
std::vector<std::string> yarp_checked(const model::App& app);

}  // namespace arbc::codegen
