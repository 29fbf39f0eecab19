// Replays a counterexample through the runtime's own evaluator (core/compiled_constraint.h)
// before it is printed (docs/design.md#the-proof): Z3 and the code that decides deliveries at run
// time must agree on every state the verifier reports. A disagreement is a bug in one of them.
#pragma once

#include <string>
#include <vector>

#include "core/constraint.h"

namespace arbc::verify {

// Evaluates `c` with CompiledConstraint in the state where exactly `present` are present.
bool runtime_holds(const Constraint& c, const std::vector<std::string>& present);

// Why `c` has its value in that state: "e_taken absent, e_arm_idle present".
std::string describe_state(const Constraint& c, const std::vector<std::string>& present);

}  // namespace arbc::verify
