// `expect exclusive M.p;` and `expect assert M.p: RULE -> EXPR;` (docs/testing.md#claims): the
// claims `arbc verify` proves about single decisions, judged on a test's run by the code that
// watches every run (runtime/decision_watch.h). A counterexample that `arbc verify
// --counterexamples` keeps as a test states the claim itself this way, so the test fails on the
// app the counterexample came from and passes once the app is fixed.
#pragma once

#include <optional>
#include <string>

#include "core/instant.h"
#include "core/test_case.h"
#include "harness/test_expect.h"

namespace arbc::harness {

struct ClaimBreach {
  Nanos t{0};
  std::string what;  // what the run did ("'left' delivered at 0s in a state where ...")
};

// The first decision of the run that breaks the claim `e` states (Kind::Exclusive or
// Kind::Assert); nullopt when every decision keeps it.
std::optional<ClaimBreach> claim_breach(const model::Expectation& e, const TestRun& run);

}  // namespace arbc::harness
