// Properties over time in `arbc verify`'s text report (docs/design.md#properties-over-time):
// the verdict with its bound and assumptions, and a violation's timed trace in spec terms.
#pragma once

#include <string>

#include "verify/report.h"

namespace arbc::verify::temporal {

// "  never two take within 1s (spec:70): ..." and, when violated, one line per step.
std::string temporal_text(const TemporalResult& r);

// The same as a diagnostic's message at the property (SARIF's result): the location says where,
// so no "(file:line)"; each step and each sentence one line, not wrapped or indented (the
// viewer wraps); the tests file of a violation is not repeated (SARIF's properties.test has it).
std::string temporal_message(const TemporalResult& r);

// The same for an editor's diagnostic at the property (the language server): as SARIF's, but a
// violation ends with its replayed tests file, which the editor has no other place to show.
std::string temporal_editor_message(const TemporalResult& r);

// The summary's count of properties by outcome, zero counts left out: "1 violated, 1 proved",
// "2 hold up to the bound". `counts` is indexed by TemporalResult::Outcome.
inline constexpr int kOutcomes = 5;  // the values of TemporalResult::Outcome
std::string outcome_counts(const size_t counts[kOutcomes]);

// The file name of the spec the property is in, as a tests file beside it names it.
std::string spec_name(const model::TemporalProperty& p);

}  // namespace arbc::verify::temporal
