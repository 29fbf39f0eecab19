// The expectations of `arbc test` (docs/testing.md#tests-in-the-spec), checked against one run:
// what the stand-ins received and the trace records.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/app_model.h"
#include "core/test_case.h"
#include "runtime/property_watch.h"
#include "runtime/stand_in.h"
#include "runtime/trace_record.h"

namespace arbc::harness {

struct TestRun {
  const std::vector<Received>& received;    // what reached the stand-ins' in-ports
  const std::vector<TraceRecord>& records;  // the trace
  Nanos end{0};                             // the last instant the run reached
  const model::App* app = nullptr;          // for the ports' types, in values it quotes
};

// "" when `e` holds in `run`; else what happened instead, in a line or a few.
std::string check_expectation(const model::Expectation& e, const TestRun& run);

// `expect PROPERTY;`: how the run broke the property; nullopt when it holds.
std::optional<PropertyBreach> property_breach(const model::Expectation& e, const TestRun& run);

// The time range a failure's trace excerpt shows: the expectation's window; for a property,
// from the first instant the breach involves to the one that broke it.
std::pair<Nanos, Nanos> failure_window(const model::Expectation& e, const TestRun& run);

// The trace records from `from` - 0.5 s to `to` + 0.5 s (at most 20 lines, the first ones),
// indented, one per line.
std::string trace_around(const TestRun& run, Nanos from, Nanos to);

// Values equal up to floating-point rounding (1e-9, relative): what `receives VALUE` compares.
// Two ints compare exactly, a NaN equals only a NaN and an infinity only the same infinity.
bool near_equal(const Value& a, const Value& b);

}  // namespace arbc::harness
