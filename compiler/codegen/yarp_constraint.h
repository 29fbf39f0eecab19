// A rule's selection constraint as YARP evaluates it (docs/yarp.md#how-the-monitors-are-written).
#pragma once

#include <string>

#include "compiler/codegen/yarp_names.h"
#include "core/app_model.h"

namespace arbc::codegen {

// What connection `c` selects on, over YARP event names: its constraint, and the events its
// own accept sets (or unsets, when nobody else sets them) on every accepting path, which YARP
// evaluates after accept, so they hold at the decision exactly as in the effective guard
// (docs/design.md#effective-guards). Each spec event becomes the disjunction of its owners'
// YARP names in the port (`false` when nobody sets it there). Every token and parenthesis is
// surrounded by spaces, as YARP's substitution needs.
std::string yarp_constraint(const model::App& app, const model::Connection& c,
                            const YarpNames& names);

// `c` as text over YARP names in `port` (the spacing above).
std::string yarp_constraint_text(const Constraint& c, const std::string& port,
                                 const YarpNames& names);

}  // namespace arbc::codegen
