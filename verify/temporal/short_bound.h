// A response checked to a bound too small for any of its windows to close (docs/checks.md,
// temporal-bound). With rates, every run in the search is short: the rated sources fill the
// bound with their messages before a window of the property's length has passed, so "holds up
// to the bound" would be true of any app. That verdict must not pass for a check.
#pragma once

#include <optional>

#include "verify/report.h"

namespace arbc::verify::temporal {

// The warning (an error with `strict`) for a response that holds up to a bound below its
// window_bound; nullopt for anything else.
std::optional<Finding> short_bound_finding(const TemporalResult& t, bool strict);

// The warning (an error with `strict`) for a vacuous property: its event can never be present in
// its port's container. The note names the ports whose containers something does put it into
// (core/event_facts.h): one name in two containers is two facts. nullopt for anything else.
std::optional<Finding> vacuous_finding(const model::App& app, const TemporalResult& t, bool strict);

}  // namespace arbc::verify::temporal
