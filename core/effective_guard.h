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

// E_c without act_c: what the runtime evaluates at c's decision (runtime_create.cc). For a
// monitor that does what app.json says it does, it holds exactly when G_c does, since accept
// has just set the must-set events and unset the must-unset ones. A monitor that does not (an
// app.json edited after the build, so that it claims a `must_set` its Lua lacks) is held to
// the model the proof was about: its message is not selected, rather than delivered in a state
// the proof took to be impossible.
Constraint decision_guard(std::span<const Connection* const> into, const Connection& rule);

}  // namespace arbc::model
