// Runs one `test` of a spec (core/test_case.h) on the embedded runtime in simulated time
// (docs/testing.md): every module is a stand-in (runtime/stand_in.h), the test's inputs are
// published at their times in the order written, events given directly are set by a harness
// connection into each arbitrated port, and the expectations are checked against what the
// stand-ins received and the trace. Deterministic: the same test gives the same outcome.
#pragma once

#include <string>
#include <vector>

#include "compiler/lower/lowered_app.h"
#include "core/app_model.h"
#include "core/diagnostic.h"
#include "core/test_case.h"
#include "runtime/claim_watch.h"
#include "runtime/stand_in.h"
#include "runtime/trace_record.h"

namespace arbc::harness {

struct TestOutcome {
  std::string name;
  bool passed = false;
  // For a failure: each failed expectation, what happened instead and the trace around it;
  // and each claim or assumption of the proof the run broke (runtime checks).
  std::string detail;
  double seconds = 0;  // wall time of the run
  // With RuntimeChecks::Warn: the broken claims and assumptions, said but not failed.
  std::string warnings;
};

// The harness monitor (monitors/arbc_test_events.lua) that `set`/`unset` steps go through;
// written once into `app_dir` before tests run there. False with *err when it cannot be.
bool write_test_harness(const std::string& app_dir, std::string* err);

// An app made ready for its tests: `lowered`'s monitors and app.json written into
// `scratch`/<app>/ with the test harness, and the app loaded back as the runtime reads it.
struct TestApp {
  bool ok = false;
  std::string dir;      // scratch/<app>
  model::App app;       // as loaded from dir
  std::string error;    // !ok: why, one problem per line ("" when generating failed)
  Diagnostic app_json;  // !ok and app.json's text was at fault: the place in it
  bool generate_failed = false;
};
TestApp write_test_app(const lower::LoweredApp& lowered, const std::string& scratch);

// What one run of a test did: the trace, what the stand-ins received, the runtime's reports.
struct TestTrace {
  std::vector<TraceRecord> records;
  std::vector<Received> received;
  std::vector<std::string> reports;
  Nanos end{0};                          // the last instant the run reached
  std::vector<ClaimViolation> breaches;  // with `watch`: the claims and assumptions it broke
};

// Runs `test` as run_test_case does and keeps what happened; false and *err when the app did
// not start. `watch`: check the proof's claims and assumptions on the run (runtime/claim_watch.h,
// in its `test` scope: a source's rate is judged between its first and last message).
bool run_test_trace(const model::App& app, const std::string& app_dir, const model::TestCase& test,
                    TestTrace* out, std::string* err, bool watch = false);

// What a test does with a run that breaks a claim or an assumption of the proof
// (`arbc test --runtime-checks`, as `arbc run`'s): fail the test, say it, or not look.
enum class RuntimeChecks { Fail, Warn, Off };

// Runs `test` on `app` (built into `app_dir`, with the harness written). A test `on RULE`
// runs that rule's connection alone, between stand-ins of its two modules.
TestOutcome run_test_case(const model::App& app, const std::string& app_dir,
                          const model::TestCase& test, RuntimeChecks checks = RuntimeChecks::Fail);

}  // namespace arbc::harness
