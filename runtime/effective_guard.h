// The effective guard of a rule (DESIGN.md section 5):
//   E_c = G_c and (events c sets on every accepting path)
//             and not (events c unsets on every such path that no other connection of the port sets)
// A `script` rule is opaque: E_c = G_c. The verifier proves facts about effective guards, and
// the docs' decision tables show them, so both read this one definition.
#pragma once

#include <string_view>

#include "runtime/app_model.h"

namespace arbc::model {

Constraint effective_guard(const App& app, std::string_view port, const Connection& rule);

}  // namespace arbc::model
