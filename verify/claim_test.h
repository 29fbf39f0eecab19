// A counterexample to a claim about single decisions (docs/checks.md#exclusive, #assert) as a
// test of the app that `arbc test` runs (issue 39: a kept counterexample is a regression test):
// the counterexample's event state given with `set` steps, then messages the rules accept, and
// an expectation that states the claim itself (`expect exclusive M.p;`, `expect assert M.p:
// RULE -> EXPR;`), which harness/claim_expect.h judges on the run as the runtime checks do. So
// the test fails on the app the counterexample came from and passes once no rule the claim
// names is selected in that state for those messages.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/test_case.h"
#include "core/value.h"
#include "verify/data_query.h"
#include "verify/report.h"
#include "verify/solver_watchdog.h"
#include "verify/verify.h"

namespace arbc::verify {

// What to replay: the state, and per rule the message it decides on (nullopt: any message it
// accepts, found by `data`). Rules of one source given one message share it (one step: both
// decide on the same message, as the data exclusivity counterexample says).
struct DecisionReplay {
  std::string name;  // the test's name
  EventState state;
  std::vector<const model::Connection*> rules;
  std::vector<std::optional<Value>> messages;  // parallel to rules
  model::Expectation claim;  // Kind::Exclusive, Kind::Assert or Kind::Resource, with its text
  // Each rule its own message, in order, even two of one source (a resource's two decisions one
  // after the other); else rules of one source share the first one's.
  bool message_per_rule = false;
  // Why a replay may keep the claim, said when it does; empty: a monitor of the same source may
  // change the events before the decision.
  std::string kept_because = {};
};

// The solver that finds the messages of these tests, made at its first question, in a Z3
// context of its own: questions asked in the checks' context change the models Z3 gives the
// checks after them (verify's goldens moved), and so their counterexamples.
class ReplayData {
 public:
  ReplayData(const model::App& app, int list_bound, Clock::time_point deadline)
      : app_(app), list_bound_(list_bound), deadline_(deadline) {}
  DataQuery& data();
  // The run's watchdog, which then watches this context too once it is made: it must be
  // destroyed before this (declare this first).
  void watched_by(SolverWatchdog& watchdog) { watchdog_ = &watchdog; }

 private:
  const model::App& app_;
  int list_bound_;
  Clock::time_point deadline_;
  SolverWatchdog* watchdog_ = nullptr;
  std::unique_ptr<z3::context> ctx_;
  std::unique_ptr<DataQuery> data_;
};

// The test; nullopt with *why_not ("'take' is opaque for data (a script)") when some rule has
// no message to replay it with, the state has an event a test cannot `set` (a hold's activity
// event), or `replayer` ran the test and its claim held (a monitor of the same source changed
// the events before the decision, say): a test that passes on the app it came from would keep
// nothing. Without a replayer the test is not run.
std::optional<model::TestCase> decision_test(const DecisionReplay& r, DataQuery& data,
                                             const TestReplayer* replayer, std::string* why_not);

// The expectations `expect exclusive PORT;`, `expect assert PORT: RULE -> EXPR;` and
// `expect resource NAME;`.
model::Expectation exclusive_claim(const std::string& port);
model::Expectation resource_claim(const std::string& name);
model::Expectation assert_claim(const std::string& port, const model::Assertion& a);

// A replayed counterexample as the text of a tests file for the spec at `spec_path` (relative to
// the file): a header that says what it is, the test's steps, then `expect CLAIM;` (`claim`
// written as is: "exclusive Wheel.cmd", "never two take within 1s"), never the deliveries of the
// bad run, so the file tests the claim.
// `header`: comment lines that say where the counterexample came from.
std::string counterexample_file_text(const model::TestCase& replay, const std::string& claim,
                                     const std::string& spec_path, const std::string& header);

// The header of a decision counterexample's file (decision_test).
extern const char* const kDecisionTestHeader;

}  // namespace arbc::verify
