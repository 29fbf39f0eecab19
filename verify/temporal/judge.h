// Whether what the runtime did in a replay violates a property over time
// (docs/design.md#properties-over-time): the verdict "violated" needs the runtime's word, not
// the model's. Each shape is judged on the port's records in the order they happened.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"
#include "verify/verify.h"

namespace arbc::verify::temporal {

// True when `records` (of p's port) violate `p`; otherwise false and *seen says what the
// runtime did instead ("'take' delivered at 0s, 1s"), for the internal error.
bool replay_violates(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
                     std::string* seen);

// True when the replay kept the environment assumption `a` at each delivery into the port;
// otherwise false and *broken says where it did not.
bool replay_respects(const model::Assumption& a, const std::vector<ReplayRecord>& records,
                     std::string* broken);

// Whether two of `times` (ascending) are less than `window` apart.
bool spaced_less_than(const std::vector<Nanos>& times, Nanos window);

}  // namespace arbc::verify::temporal
