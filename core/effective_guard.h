// The effective guard of a rule (docs/design.md#effective-guards):
//   E_c = G_c and (events c sets on every accepting path)
//             and not (events c unsets on every such path that no other connection of the port
//             sets, a `script` rule counting as one that may set any event)
//             and act_c (`by priority`: the activity event the runtime sets when c delivers)
// A `script` rule is opaque: E_c = G_c and act_c. The activity event is set after the
// decision, on delivery only, so a message that is rejected or not selected suppresses
// nothing; but c's delivery and the state it leaves are one step of the runtime, so no other
// rule's decision sees c delivered without act_c (docs/design.md#priorities-and-holds). The
// verifier proves facts about effective guards, and the docs' decision tables show them, so
// both read this one definition.
#pragma once

#include <span>
#include <string_view>

#include "core/app_model.h"

namespace arbc::model {

// `into` is every connection into the rule's port (App::connections_into). Callers that need
// the guards of all rules of a port pass it once: searching the whole app per rule is
// quadratic in the number of connections.
Constraint effective_guard(std::span<const Connection* const> into, const Connection& rule);

Constraint effective_guard(const App& app, std::string_view port, const Connection& rule);

}  // namespace arbc::model
