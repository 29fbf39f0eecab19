// The verdict of `arbc run` (its `result:` line and the report's): pure functions of what the
// run left, so that each rule has a test (cli/run_verdict_test.cc); cli/run_end.cc prints.
#pragma once

#include <string>
#include <vector>

#include "runtime/claim_watch.h"
#include "runtime/runtime.h"

namespace arbc::cli {

struct RunVerdict {
  bool success = true;
  std::string text;  // "success", "failure (...)"
};

// A run with an environment is what the environment says.
RunVerdict judge_by_environment(bool environment_success);

// A run without an environment has no world to say whether it went well. It is judged by what
// the runtime can tell is broken: a quarantined connection (its monitor kept failing), and a
// message that could not be read as its port's type (a module, or a program across the
// transport, does not keep the port's contract; a DDS sample that does not decode is one). Such
// messages are dropped and counted; the verdict names them, so that `success` never stands over
// a run whose messages all went unread. Other drops (queue-full, bad-value, not-selected) are
// the mediation working, not a failure.
RunVerdict judge_without_environment(const std::vector<ConnectionStats>& connections,
                                     const std::vector<InputStats>& inputs);

// The runtime checks' violations (runtime/claim_watch.h) over a verdict: with `fail`
// (--runtime-checks fail) any violation makes the run a failure that names each broken claim or
// assumption and when, keeping what already failed it; without, the verdict is unchanged (the
// violations are printed, not judged).
RunVerdict with_broken_claims(RunVerdict verdict, const std::vector<ClaimViolation>& broken,
                              bool fail);

// "assumption given Nav.cmd every 100ms" for a broken assumption, the claim as written otherwise.
std::string broken_claim_name(const ClaimViolation& v);

}  // namespace arbc::cli
