#include "harness/test_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include "compiler/codegen/target.h"
#include "compiler/codegen/write_artifacts.h"
#include "core/duration_literal.h"
#include "harness/test_expect.h"
#include "runtime/app_loader.h"
#include "runtime/runtime.h"
#include "runtime/stand_in.h"

namespace arbc::harness {

namespace {

constexpr const char* kHarnessModule = "arbc_test";
constexpr const char* kHarnessMonitor = "monitors/arbc_test_events.lua";

// Sets or unsets the event a step names, for good (until the test unsets it): a test gives
// event states directly. A feed: it never delivers.
constexpr const char* kHarnessScript =
    "-- arbc test: sets and unsets the events a test gives directly (docs/testing.md).\n"
    "PortMonitor.accept = function(step)\n"
    "  if step.op == 'set' then PortMonitor.setEvent(step.event, 1e12)\n"
    "  else PortMonitor.unsetEvent(step.event) end\n"
    "  return false\n"
    "end\n";

// The app a test runs: the whole app, or one rule between its two modules.
model::App test_app(const model::App& app, const model::TestCase& test) {
  if (test.rule.empty()) return app;
  model::App sub;
  sub.name = app.name;
  sub.events = app.events;
  for (const model::Connection& c : app.connections) {
    if (c.kind != model::ConnectionKind::Rule || c.name != test.rule) continue;
    sub.connections.push_back(c);
    for (const std::string& port : {c.source, c.destination}) {
      const model::Module* m = app.find_module(port.substr(0, port.find('.')));
      if (m && !sub.find_module(m->name)) sub.modules.push_back(*m);
    }
    if (const model::ArbitratedPort* a = app.find_arbitrated(c.destination)) {
      model::ArbitratedPort only = *a;
      only.rules = {c.name};
      sub.arbitrated_ports.push_back(only);
    }
    break;
  }
  return sub;
}

// The harness module and one feed into each arbitrated port, for `set`/`unset` steps.
void add_harness(model::App& app) {
  model::Module m;
  m.name = kHarnessModule;
  model::Port out;
  out.name = "events";
  out.direction = model::Direction::Out;
  out.type = parse_type("{op: string, event: string}");
  m.ports.push_back(out);
  app.modules.push_back(m);
  for (const model::ArbitratedPort& a : app.arbitrated_ports) {
    model::Connection c;
    c.name = std::string(kHarnessModule) + "_events_" + std::to_string(app.connections.size());
    c.source = std::string(kHarnessModule) + ".events";
    c.destination = a.port;
    c.kind = model::ConnectionKind::Feed;
    c.generated = true;
    c.constraint = Constraint::constant(false);
    c.monitor = kHarnessMonitor;
    app.connections.push_back(c);
  }
}

// The last instant a test looks at: its last step, window start or finite window end.
Nanos test_end(const model::TestCase& test) {
  Nanos end{0};
  for (const model::TestStep& s : test.steps) end = std::max(end, s.t);
  Nanos last_step = end;
  for (const model::Expectation& e : test.expectations) {
    end = std::max(end, e.from);
    if (e.to != kNever) end = std::max(end, e.to);
    // A response's last trigger may come at the last step: the run goes on for its window, so
    // that an answer that never comes is judged (a window past the end is not).
    if (e.property && e.property->kind == model::TemporalProperty::Kind::Response)
      end = std::max(end, later(last_step, e.property->window));
  }
  return end;
}

// The test's steps as the stand-ins' inputs, in the order written: an input on its port, a
// `set`/`unset` on the harness module's port. The stand-ins publish them at their times, the
// steps of one instant in the order written (StandInLog::add_input), as `arbc run --inputs`
// does a file's lines (docs/testing.md#how-tests-run); a replayed counterexample needs that
// order.
void add_steps(StandInLog& log, const model::TestCase& test) {
  for (const model::TestStep& s : test.steps) {
    if (s.kind == model::TestStep::Kind::Input) {
      log.add_input({s.t, s.port, s.value});
      continue;
    }
    Value step = Value::record(
        {{"op", s.kind == model::TestStep::Kind::Set ? "set" : "unset"}, {"event", s.event}});
    log.add_input({s.t, std::string(kHarnessModule) + ".events", step});
  }
}

// Each failed expectation with what happened and the trace around it.
std::string failures(const model::TestCase& test, const TestRun& run,
                     const std::vector<std::string>& reports) {
  std::string out;
  for (const model::Expectation& e : test.expectations) {
    std::string why = check_expectation(e, run);
    if (why.empty()) continue;
    // FILE:LINE:COL, as diagnostics are: editors and CI problem matchers jump to the `expect`.
    std::string where = e.loc.file + ":" + std::to_string(e.loc.line);
    if (e.loc.column > 0) where += ":" + std::to_string(e.loc.column);
    out += "  " + where + ": expected " + e.text + "\n";
    auto [from, to] = failure_window(e, run);
    out += "  " + why + "\n  trace:\n" + trace_around(run, from, to);
  }
  if (!out.empty()) {
    for (const std::string& r : reports) out += "  runtime: " + r + "\n";
  }
  return out;
}

}  // namespace

bool write_test_harness(const std::string& app_dir, std::string* err) {
  std::filesystem::path path = std::filesystem::path(app_dir) / kHarnessMonitor;
  std::ofstream out(path);
  out << kHarnessScript;
  if (!out) {
    *err = "cannot write " + path.string();
    return false;
  }
  return true;
}

bool run_test_trace(const model::App& app, const std::string& app_dir, const model::TestCase& test,
                    TestTrace* out, std::string* err, bool watch) {
  model::App run_app = test_app(app, test);
  add_harness(run_app);
  auto log = std::make_shared<StandInLog>();
  add_steps(*log, test);
  std::vector<std::string> stand_ins;
  Registry registry = registry_with_stand_ins(run_app, Registry(), log, &stand_ins);
  RunOptions options;
  options.trace_records = &out->records;
  ClaimWatch claims(run_app, {.test = true});
  if (watch && !claims.load_claims(app_dir, err)) return false;
  if (watch && !claims.empty()) {
    options.trace_watch = [&claims](const TraceLine& r, Trace& trace) { claims.watch(r, trace); };
    options.on_start = [&claims](Nanos t) { claims.start(t); };
  }
  std::unique_ptr<Runtime> rt = Runtime::create(run_app, app_dir, options, err, registry);
  if (!rt) return false;
  rt->set_reporter([out](const std::string& line) { out->reports.push_back(line); });
  rt->start();
  out->end = test_end(test);
  rt->advance(out->end);
  rt->shutdown();
  out->received = log->received;
  if (options.trace_watch) {
    claims.finish(out->end);
    out->breaches = claims.violations();
  }
  return true;
}

TestApp write_test_app(const lower::LoweredApp& lowered, const std::string& scratch) {
  TestApp out;
  std::unique_ptr<codegen::Target> target = codegen::make_target(codegen::kDefaultTarget);
  codegen::CodegenResult generated = target->generate(lowered);
  if (!generated.ok) {
    out.generate_failed = true;
    return out;
  }
  if (!codegen::write_artifacts(scratch, lowered.app.name, generated.files, &out.error)) return out;
  out.dir = (std::filesystem::path(scratch) / lowered.app.name).string();
  std::optional<model::App> loaded = load_app_dir(out.dir, &out.error, &out.app_json);
  if (!loaded || !write_test_harness(out.dir, &out.error)) return out;
  out.app = std::move(*loaded);
  out.ok = true;
  return out;
}

TestOutcome run_test_case(const model::App& app, const std::string& app_dir,
                          const model::TestCase& test, RuntimeChecks checks) {
  auto started = std::chrono::steady_clock::now();
  TestOutcome outcome;
  outcome.name = test.name;
  TestTrace trace;
  std::string error;
  if (!run_test_trace(app, app_dir, test, &trace, &error, checks != RuntimeChecks::Off)) {
    outcome.detail = "  the app did not start: " + error + "\n";
    return outcome;
  }
  TestRun run{trace.received, trace.records, trace.end, &app};
  outcome.detail = failures(test, run, trace.reports);
  // The run left what the proof covers: a failure of the test, as of `arbc run`.
  std::string breaches;
  for (const ClaimViolation& v : trace.breaches)
    breaches += "  runtime check: " + std::string(v.assumption ? "assumption " : "") + v.claim +
                " broken at " + duration_literal(v.t) + ": " + v.what + "\n";
  (checks == RuntimeChecks::Fail ? outcome.detail : outcome.warnings) += breaches;
  outcome.passed = outcome.detail.empty();
  outcome.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return outcome;
}

}  // namespace arbc::harness
