// The precedence property `only RULE after OTHER;` (docs/design.md#properties-over-time): is
// there a run in which RULE delivers without a delivery of OTHER since its previous delivery
// (or since the start, for its first)? Bounded model checking over 1, 2, ... messages into the
// port both rules go into, then k-induction for an unbounded proof (verify/temporal/induction.h).
#pragma once

#include <z3++.h>

#include <chrono>
#include <optional>
#include <string>

#include "core/app_model.h"
#include "verify/data_query.h"
#include "verify/report.h"

namespace arbc::verify::temporal {

// As check_spacing (verify/temporal/spacing.h); nullopt and *err when the port lacks either rule.
std::optional<TemporalResult> check_precedence(const model::App& app,
                                               const model::TemporalProperty& p, int bound,
                                               z3::context& ctx, DataQuery* data,
                                               std::chrono::steady_clock::time_point deadline,
                                               std::string* err, bool faithful = false);

}  // namespace arbc::verify::temporal
