// The absence property `never RULE while EVENT;` (docs/design.md#properties-over-time): is
// there a run in which RULE delivers at a decision where EVENT is present in its port's
// container? Bounded model checking over 1, 2, ... messages, then a proof for runs of any
// length where one decision state already rules it out.
#pragma once

#include <z3++.h>

#include <chrono>
#include <optional>
#include <string>

#include "core/app_model.h"
#include "verify/data_query.h"
#include "verify/report.h"

namespace arbc::verify::temporal {

// As check_spacing (verify/temporal/spacing.h): the verdict up to `bound` messages, Proved when
// the single-instant argument applies, nullopt and *err for a port or rule the model lacks.
std::optional<TemporalResult> check_absence(const model::App& app, const model::TemporalProperty& p,
                                            int bound, z3::context& ctx, DataQuery* data,
                                            std::chrono::steady_clock::time_point deadline,
                                            std::string* err, bool faithful = false);

}  // namespace arbc::verify::temporal
