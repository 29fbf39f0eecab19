#include "verify/verify.h"

#include <algorithm>
#include <cstdio>

#include "verify/port_checks.h"
#include "verify/port_scope.h"
#include "verify/resource_checks.h"
#include "verify/solver_watchdog.h"
#include "verify/structural_checks.h"
#include "verify/temporal/confirm.h"
#include "verify/temporal/property.h"
#include "verify/temporal/short_bound.h"

namespace arbc::verify {
namespace {

bool has_error(const std::vector<Finding>& findings) {
  for (const Finding& f : findings) {
    if (f.severity == Severity::Error && f.check != kCheckUnknown) return true;
  }
  return false;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A property over time decided in the abstract model, a violation replayed on the runtime
// (docs/design.md#properties-over-time). A violation the runtime does not show is searched for
// again among the runs a replay can make (PortShape::faithful); one found there and shown is the
// verdict. None found there: "holds up to the bound" under what those runs take for granted,
// which the verdict prints; a proof needs the free model. Never a violation the runtime does
// not show.
std::optional<TemporalResult> decide_temporal(const model::App& app,
                                              const model::TemporalProperty& p,
                                              const VerifyOptions& options, z3::context& ctx,
                                              DataQuery& data, Clock::time_point deadline,
                                              VerifyReport& report, std::string* err) {
  std::optional<TemporalResult> t =
      temporal::check_property(app, p, options.temporal_bound, ctx, &data, deadline, err);
  std::string seen;
  if (!t || temporal::confirm_violation(options.test_replayer, *t, report.app_findings, &seen) !=
                temporal::Confirmation::NotShown)
    return t;
  std::optional<TemporalResult> again = temporal::check_property(
      app, p, options.temporal_bound, ctx, &data, deadline, err, /*faithful=*/true);
  if (!again) return std::nullopt;
  std::string seen_again;
  again->solver_queries += t->solver_queries;
  again->faithful = true;
  if (again->outcome == TemporalResult::Outcome::Violated &&
      temporal::confirm_violation(options.test_replayer, *again, report.app_findings,
                                  &seen_again) == temporal::Confirmation::Shown)
    return again;
  // No violation among those runs: bounded, and under what they take for granted (a proof of
  // the faithful model, by induction or at one decision, says nothing of the other runs).
  if (again->outcome == TemporalResult::Outcome::HoldsToBound ||
      again->outcome == TemporalResult::Outcome::Proved) {
    again->outcome = TemporalResult::Outcome::HoldsToBound;
    again->proof.clear();
    again->induction_k = 0;
    return again;
  }
  t->solver_queries = again->solver_queries;
  t->outcome = TemporalResult::Outcome::Unknown;
  t->unknown_reason =
      "violated in the model, but the runtime does not show it (" + seen +
      "); among the runs a replay makes (each message of a source handed to all its rules and "
      "feeds into " +
      p.port + " at one instant), " +
      (again->outcome == TemporalResult::Outcome::Violated
           ? "the violation found does not replay either (" + seen_again + ")"
           : "the search ended unknown (" + again->unknown_reason + ")");
  t->trace.clear();
  t->replay_test.reset();
  return t;
}

// Properties over time, each decided by decide_temporal. False and *err on a malformed model.
bool check_temporal(const model::App& app, const VerifyOptions& options, z3::context& ctx,
                    DataQuery& data, Clock::time_point deadline, VerifyReport& report,
                    std::string* err) {
  for (const model::TemporalProperty& p : app.temporal) {
    std::optional<TemporalResult> t =
        decide_temporal(app, p, options, ctx, data, deadline, report, err);
    if (!t) return false;
    if (auto f = temporal::short_bound_finding(*t, options.strict))
      report.app_findings.push_back(std::move(*f));
    if (auto f = temporal::vacuous_finding(app, *t, options.strict))
      report.app_findings.push_back(std::move(*f));
    report.solver_queries += t->solver_queries;
    report.temporal.push_back(std::move(*t));
  }
  return true;
}

}  // namespace

namespace {

// What the data answers assumed, and the rules whose answers rested on the list bound (app.json
// carries it on them, so that the runtime drops longer lists).
void data_assumptions(const DataQuery& data, const VerifyOptions& options, VerifyReport& report) {
  report.solver_queries += data.queries();
  if (data.queries() == 0) return;
  // Lists of any length unless some answer rested on the bound (DataQuery::bound_used).
  for (const model::Connection* c : data.bounded_rules())
    report.bounded_rules.emplace_back(c->destination, c->name);
  std::sort(report.bounded_rules.begin(), report.bounded_rules.end());
  if (data.bound_used()) {
    report.list_bound = options.list_bound;
    report.assumptions.push_back("lists in messages have at most " +
                                 std::to_string(options.list_bound) + " elements (--list-bound)");
  }
  report.assumptions.push_back(
      "monitor state (var, now()) may hold any value earlier messages could leave");
}

}  // namespace

namespace {

std::optional<VerifyReport> verify_within_deadline(const model::App& app,
                                                   const VerifyOptions& options, std::string* err) {
  VerifyReport report;
  report.app = app.name;
  report.spec_file = app.spec_file;
  Clock::time_point start = Clock::now();
  Clock::time_point deadline =
      start + std::chrono::duration_cast<Clock::duration>(
                  std::chrono::duration<double>(std::max(0.0, options.timeout_seconds)));

  std::vector<PortScope> scopes;
  for (const model::ArbitratedPort& port : app.arbitrated_ports) {
    std::optional<PortScope> scope = build_port_scope(app, port, err);
    if (!scope) return std::nullopt;
    scopes.push_back(std::move(*scope));
  }

  std::vector<Finding> structural;
  run_structural_checks(app, options.strict, structural);

  z3::context ctx;  // one per run: creating a context costs tens of milliseconds
  ReplayData replay(app, options.list_bound, deadline);      // outlives the watchdog, which sees it
  SolverWatchdog watchdog(ctx, deadline, options.on_stuck);  // where Z3's timeout is not kept
  replay.watched_by(watchdog);
  DataQuery data(app, ctx, options.list_bound, deadline);
  for (const PortScope& scope : scopes) {
    PortResult result;
    Clock::time_point port_start = Clock::now();
    run_port_checks(scope, options, ctx, deadline, data, replay, result);
    for (Finding& f : structural) {
      if (f.port == result.port) result.findings.push_back(std::move(f));
    }
    result.seconds = seconds_since(port_start);
    if (has_error(result.findings)) {
      result.verdict = Verdict::Refuted;
    } else if (!result.unknown_reason.empty()) {
      result.verdict = Verdict::Unknown;
    } else {
      result.verdict = Verdict::Proved;
    }
    report.solver_queries += result.solver_queries;
    report.ports.push_back(std::move(result));
  }
  for (Finding& f : structural) {
    if (!f.check.empty() && f.port.empty()) report.app_findings.push_back(std::move(f));
  }
  run_resource_checks(app, scopes, options, ctx, deadline, data, report);

  bool refuted = has_error(report.app_findings);
  bool unknown = false;
  for (const PortResult& p : report.ports) {
    refuted |= p.verdict == Verdict::Refuted;
    unknown |= p.verdict == Verdict::Unknown;
  }
  if (!check_temporal(app, options, ctx, data, deadline, report, err)) return std::nullopt;
  refuted |= has_error(report.app_findings);
  for (const TemporalResult& t : report.temporal) {
    // Bounded: "holds up to the bound" leaves the verdict as it is.
    refuted |= t.outcome == TemporalResult::Outcome::Violated;
    unknown |= t.outcome == TemporalResult::Outcome::Unknown;
  }
  for (const ResourceResult& r : report.resources) {
    refuted |= r.verdict == Verdict::Refuted;
    unknown |= r.verdict == Verdict::Unknown;
  }
  data_assumptions(data, options, report);
  report.verdict = refuted ? Verdict::Refuted : unknown ? Verdict::Unknown : Verdict::Proved;
  report.seconds = seconds_since(start);
  return report;
}

}  // namespace

std::optional<VerifyReport> verify_app(const model::App& app, const VerifyOptions& options,
                                       std::string* err) {
  Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(std::max(0.0, options.timeout_seconds)));
  try {
    return verify_within_deadline(app, options, err);
  } catch (const z3::exception&) {
    // Past the deadline the watchdog interrupts the context, and what Z3 is asked after that
    // outside a query throws: "push canceled", or "there is no current model" for a check the
    // interrupt ended (drt seed 38 spec 60 under load; tests/verify/timeout_sweep.sh). The time
    // is up, not a bug; before the deadline an exception is one.
    if (Clock::now() < deadline) throw;
    return stuck_report(app, options.timeout_seconds, /*stuck=*/false);
  }
}

VerifyReport stuck_report(const model::App& app, double timeout_seconds, bool stuck) {
  VerifyReport report;
  report.app = app.name;
  report.spec_file = app.spec_file;
  report.verdict = Verdict::Unknown;
  for (const model::ArbitratedPort& port : app.arbitrated_ports) {
    PortResult r;  // listed, so the report does not read as an app without ports
    r.port = port.port;
    r.by_priority = port.by_priority;
    r.loc = port.loc;
    r.rules = port.rules;
    r.verdict = Verdict::Unknown;
    r.unknown_reason = "timeout";
    report.ports.push_back(std::move(r));
  }
  Finding f;
  f.check = kCheckUnknown;
  f.severity = Severity::Error;
  char limit[32];
  std::snprintf(limit, sizeof limit, "%gs", timeout_seconds);
  f.message = std::string("no verdict within the time limit (--timeout ") + limit + "): " +
              (stuck ? "the solver did not stop when interrupted, so the checks after that query "
                       "did not run (Z3 4.8 does not always stop inside nonlinear arithmetic)"
                     : "the time ran out before every check had run");
  f.notes.push_back({stuck ? "raise --timeout, or write the rule without multiplying, dividing or "
                             "taking norms of message fields; report the spec if it is small"
                           : "raise --timeout",
                     {}});
  report.app_findings.push_back(std::move(f));
  return report;
}

}  // namespace arbc::verify
