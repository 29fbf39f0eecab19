// A constraint over events (core/constraint.h) as a Z3 Boolean, for the properties over time
// (docs/design.md#properties-over-time): the unrolling reads each event as its presence at a
// step's decision, the single-instant proof of an absence as a free Boolean.
#pragma once

#include <z3++.h>

#include <functional>
#include <string>

#include "core/constraint.h"

namespace arbc::verify::temporal {

// `c` with each event e replaced by `present(e)`.
z3::expr constraint_expr(const Constraint& c, z3::context& ctx,
                         const std::function<z3::expr(const std::string&)>& present);

}  // namespace arbc::verify::temporal
