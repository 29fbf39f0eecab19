// One property over time, whatever its shape (docs/design.md#properties-over-time): the checker
// of its kind, and the words that name it in reports and counterexample tests.
#pragma once

#include <z3++.h>

#include <chrono>
#include <optional>
#include <string>

#include "core/app_model.h"
#include "verify/data_query.h"
#include "verify/report.h"

namespace arbc::verify::temporal {

// check_spacing, check_absence, check_precedence or check_response, by p.kind.
std::optional<TemporalResult> check_property(const model::App& app,
                                             const model::TemporalProperty& p, int bound,
                                             z3::context& ctx, DataQuery* data,
                                             std::chrono::steady_clock::time_point deadline,
                                             std::string* err, bool faithful = false);

// The property as the spec states it: "never two take within 1s", "never search while
// act_track", "only put after take".
std::string property_words(const model::TemporalProperty& p);

}  // namespace arbc::verify::temporal
