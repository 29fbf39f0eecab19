// The response property `after OTHER [stops], RULE within D [while C];` by bounded model
// checking (docs/design.md#properties-over-time): is there a run in which OTHER delivers at
// t (with `stops`: and not again until t + D), time reaches t + D, and RULE has not delivered
// since, although C held at each of RULE's decisions in between? Time passing is the run's
// horizon, t + D: with no rate given for RULE's source, silence (no message at all) violates
// it, and the report says so. The rates (`given M.p every D`, verify/temporal/rates.h) of the
// port's sources hold up to the horizon.
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
std::optional<TemporalResult> check_response(const model::App& app,
                                             const model::TemporalProperty& p, int bound,
                                             z3::context& ctx, DataQuery* data,
                                             std::chrono::steady_clock::time_point deadline,
                                             std::string* err, bool faithful = false);

}  // namespace arbc::verify::temporal
