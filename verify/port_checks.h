// The solver checks of one arbitrated port (docs/checks.md): exclusive, dead, complete,
// assert, each counterexample minimal (fewest events present) and replayed through the
// runtime's evaluator before it is reported.
#pragma once

#include "verify/claim_test.h"
#include "verify/data_query.h"
#include "verify/port_scope.h"
#include "verify/port_solver.h"
#include "verify/report.h"
#include "verify/verify.h"

namespace arbc::verify {

// Fills `result` (rules, events, invariants used, findings, verdict) for the port in `scope`.
// Pairs of rules with one source that overlap in events are asked about data (`data`); the
// messages of the tests that replay its counterexamples, of `replay` (verify/claim_test.h).
void run_port_checks(const PortScope& scope, const VerifyOptions& options, z3::context& ctx,
                     Clock::time_point deadline, DataQuery& data, ReplayData& replay,
                     PortResult& result);

}  // namespace arbc::verify
