// The spacing property `never two RULE within W;` by bounded model checking
// (docs/design.md#properties-over-time): is there a run in which RULE delivers twice less than
// W apart, within `bound` messages into its port? Tries 2, 3, ... messages, so a violation found
// is one of the fewest messages. `never RULE within W after OTHER;` (p.other) asks the same of
// a delivery of RULE less than W after one of OTHER.
#pragma once

#include <z3++.h>

#include <chrono>
#include <optional>
#include <string>

#include "core/app_model.h"
#include "verify/data_query.h"
#include "verify/report.h"
#include "verify/temporal/bmc.h"

namespace arbc::verify::temporal {

// The verdict for `p` up to `bound` messages in the abstract model; unknown when the deadline
// passes. A violation comes with its trace and, when `data` finds a message for every rule
// step, the trace as a test to replay (TemporalResult::replay_test). nullopt and *err when `p`
// names a port or rule the model does not have (bad input, not a verdict).
std::optional<TemporalResult> check_spacing(const model::App& app, const model::TemporalProperty& p,
                                            int bound, z3::context& ctx, DataQuery* data,
                                            std::chrono::steady_clock::time_point deadline,
                                            std::string* err, bool faithful = false);

}  // namespace arbc::verify::temporal
