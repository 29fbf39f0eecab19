// The verifier's public API (docs/design.md#the-proof): proves, per arbitrated port, that no
// decision state selects two rules, and runs the other checks (dead, unfed, unused, ownership,
// complete, assert). Reads the core model only, so `arbc verify SPEC` (after lowering) and `arbc
// verify app.json` give the same proof.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/test_case.h"
#include "core/value.h"
#include "verify/report.h"

namespace arbc::verify {

// Overlapping pairs of one port reported with a counterexample; the rest are counted.
inline constexpr int kDefaultMaxPairsPerPort = 10;

// What a monitor did with one message (docs/checks.md#message-data).
struct MonitorRun {
  bool accepted = false;
  std::string reason;  // why it was dropped, when not accepted
  Value delivered;     // when accepted
};

// Runs a connection's generated monitor on a message, as the runtime does; the CLI provides
// one backed by the runtime's Lua monitors, so every message counterexample is replayed.
class MonitorRunner {
 public:
  virtual ~MonitorRunner() = default;
  virtual bool run(const model::Connection& c, const Value& message, MonitorRun* out,
                   std::string* err) const = 0;
};

// What the runtime did at one arbitrated port during a replay, in the order it happened: a
// delivery, a message a rule handled without delivering it (rejected, throttled, not
// selected), or an entry of the port's container set or removed (unset, or lapsed).
struct ReplayRecord {
  enum class Kind { Deliver, Drop, Set, Remove };
  Kind kind = Kind::Deliver;
  Nanos t{0};
  std::string connection;  // Deliver, Drop: the rule; Set, Remove: the entry's owner
  std::string event;       // Set, Remove
  Nanos expiry = kNever;   // Set: the entry's expiry; kNever: none (until removed)
};

// Runs a test of the app on the runtime in simulated time, as `arbc test` does; the CLI
// provides one, so every counterexample over time is replayed before it is reported
// (docs/design.md#properties-over-time). Returns what happened at port `port`; nullopt and
// *err when the run could not be made.
class TestReplayer {
 public:
  virtual ~TestReplayer() = default;
  virtual std::optional<std::vector<ReplayRecord>> replay(const model::TestCase& test,
                                                          const std::string& port,
                                                          std::string* err) const = 0;
  // Runs `test` as `arbc test` does and judges its expectations: "" when they all hold, else the
  // first failure in words; nullopt and *err when the run could not be made (or this replayer
  // cannot judge). A counterexample written as a test is run so before it is written
  // (verify/claim_test.h): it must fail on the app it came from.
  virtual std::optional<std::string> judge(const model::TestCase&, std::string* err) const {
    *err = "no runtime to run it on";
    return std::nullopt;
  }
};

struct VerifyOptions {
  double timeout_seconds = 60;  // for the whole app; a query cut short answers unknown
  bool strict = false;          // warnings (dead, unused) become errors
  int max_pairs_per_port = kDefaultMaxPairsPerPort;
  // Messages into a port that properties over time are explored to
  // (docs/design.md#properties-over-time).
  int temporal_bound = 8;
  int list_bound = 4;  // lists in messages have at most this many elements (--list-bound)
  // Replays message counterexamples through the Lua monitors (the CLI always gives one); without
  // one a data finding is reported with the note "not replayed (no monitor runner)".
  const MonitorRunner* runner = nullptr;
  // Replays counterexamples over time; without one, a violation found in the model cannot be
  // confirmed and is reported as unknown.
  const TestReplayer* test_replayer = nullptr;
  // Called once, on another thread, when a solver query has not returned 5 s after the
  // deadline although interrupted (Z3 does not always stop: verify/solver_watchdog.h). The
  // call inside Z3 cannot be ended; a command line ends the process with the verdict unknown.
  std::function<void()> on_stuck;
};

// Verifies every arbitrated port of `app`. Never throws; solver trouble becomes an unknown
// verdict, a Z3/runtime disagreement an `internal` error finding. nullopt (and `err`) when the
// model is malformed for verification (a port names a rule that does not go into it, an assert
// names an unknown rule): a bad-input error, not a finding.
std::optional<VerifyReport> verify_app(const model::App& app, const VerifyOptions& options,
                                       std::string* err);

// The report of an app whose verification could not be ended at the deadline (on_stuck): the
// verdict unknown, every port unknown, one app finding saying why, and nothing else (the checks
// after the stuck query never ran).
// `stuck`: the solver did not stop when interrupted (SolverWatchdog's on_stuck); else the
// deadline passed between queries and Z3 refused further work ("canceled").
VerifyReport stuck_report(const model::App& app, double timeout_seconds, bool stuck = true);

}  // namespace arbc::verify
