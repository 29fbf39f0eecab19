// A timed counterexample as a test of the app (core/test_case.h) that `arbc test` runs on the
// runtime in simulated time (docs/design.md#properties-over-time): each rule step of the trace
// becomes a message on its source that the rule's monitor accepts (a witness from the data
// proofs, verify/data_query.h), and what the trace's feeds did to the port's container becomes
// `set`/`unset` steps, as a test gives event states directly.
#pragma once

#include <z3++.h>

#include <optional>
#include <string>

#include "core/app_model.h"
#include "core/test_case.h"
#include "verify/data_query.h"
#include "verify/temporal/unrolling.h"

namespace arbc::verify::temporal {

// The test for the `steps` steps of `u` in model `m`, violating `p`; nullopt with *why_not
// ("'take' is opaque for data (a script)") when some step has no message to replay it with.
std::optional<model::TestCase> counterexample_test(const PortShape& shape, const Unrolling& u,
                                                   const z3::model& m, int steps,
                                                   const model::TemporalProperty& p,
                                                   DataQuery& data, std::string* why_not);

// The counterexample as the text of a tests file for the spec at `spec_path` (relative to the
// file): the replay's steps, then `expect PROPERTY;` (runtime/property_watch.h judges it), so
// the file fails on the app the counterexample came from and passes once the app no longer
// breaks `p` on those inputs (issue 39: a kept counterexample is a regression test).
std::string test_file_text(const model::TestCase& replay, const model::TemporalProperty& p,
                           const std::string& spec_path);

}  // namespace arbc::verify::temporal
