// The stability property `stable M.p for D;` by bounded model checking
// (docs/design.md#properties-over-time): is there a run in which the rule delivering into M.p
// changes twice less than D apart? A switch is a delivery by a rule other than the one that
// delivered last (the first delivery is no switch). Bounded search over 3, 4, ... messages
// (two switches need three deliveries); no unbounded argument.
#pragma once

#include <z3++.h>

#include <chrono>
#include <optional>
#include <string>

#include "core/app_model.h"
#include "verify/data_query.h"
#include "verify/report.h"

namespace arbc::verify::temporal {

// As check_spacing (verify/temporal/spacing.h); nullopt and *err when M.p is not arbitrated.
std::optional<TemporalResult> check_stability(const model::App& app,
                                              const model::TemporalProperty& p, int bound,
                                              z3::context& ctx, DataQuery* data,
                                              std::chrono::steady_clock::time_point deadline,
                                              std::string* err, bool faithful = false);

}  // namespace arbc::verify::temporal
