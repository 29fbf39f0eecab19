// A short disjunction of conjunctions for a truth table (Quine-McCluskey prime implicants and
// a greedy cover), so that YARP's answers read as `e_face` rather than as one term per state.
#pragma once

#include <string>
#include <vector>

#include "core/constraint.h"

namespace arbc::yarp {

// `events[i]` is bit i of each mask in `true_states`; at most 16 events.
Constraint minimal_dnf(const std::vector<std::string>& events,
                       const std::vector<unsigned>& true_states);

}  // namespace arbc::yarp
