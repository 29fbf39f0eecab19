// `arbc test SPEC... [--filter GLOB] [--junit FILE] [--no-verify] [--jobs N]`
// (docs/testing.md): runs the `test` declarations of each spec on the embedded runtime in
// simulated time, one line per test, the details of each failure. Each spec is compiled and,
// unless --no-verify, proved first (as `arbc run` does), all of them before any test runs.
// Exit: 0 every test passed, 1 a test failed (or a proof was refuted), 2 bad input (a --filter
// that matches none of the tests declared included).
#include <stdlib.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "cli/commands.h"
#include "cli/msg_path_option.h"
#include "cli/parse_error.h"
#include "cli/verify_gate.h"
#include "compiler/codegen/target.h"
#include "compiler/codegen/write_artifacts.h"
#include "compiler/frontend/frontend.h"
#include "compiler/lower/compile_spec.h"
#include "core/diagnostic.h"
#include "core/join.h"
#include "harness/junit.h"
#include "harness/test_filter.h"
#include "harness/test_runner.h"
#include "runtime/app_loader.h"

namespace arbc::cli {

namespace {

namespace fs = std::filesystem;

struct TestArgs {
  std::vector<std::string> specs;
  std::string filter = "*", junit;
  bool no_verify = false;
  unsigned jobs = 0;                    // 0: one per core when there are many tests
  std::string runtime_checks = "fail";  // --runtime-checks: fail, warn or off
};

// A scratch directory for one spec's build, removed at the end.
struct Scratch {
  std::string path;
  ~Scratch() {
    std::error_code ignored;
    if (!path.empty()) fs::remove_all(path, ignored);
  }
};

// One spec ready to run its tests.
struct PreparedSpec {
  std::string spec;
  Scratch scratch;
  std::string dir;
  model::App app;
  std::vector<model::TestCase> tests;
};

// What earlier specs of the same `arbc test` printed and proved. A tests file compiles and
// proves the app it tests: given beside that app's spec (or another of its tests files), its
// errors and the proof's report would be printed again, and the proof run again.
struct Seen {
  std::set<std::string> diagnostics;  // rendered
  // The app's spec file (canonical) -> its proof's gate: whether it passed (else its exit), and
  // the rules it holds for only up to the list bound.
  std::map<std::string, VerifyGate> gates;
};

// The spec compiled, proved (unless no_verify) and written to a scratch directory, with the
// test harness; its tests. Returns an exit code (kExitOk: *app_dir, *app and *tests are set).
int prepare_spec(const std::string& spec, bool no_verify, Seen* seen, Scratch* scratch,
                 std::string* app_dir, model::App* app, std::vector<model::TestCase>* tests) {
  lower::CompiledSpec compiled = lower::compile_spec(spec);
  std::vector<Diagnostic> fresh;
  for (const Diagnostic& d : compiled.diagnostics) {
    if (seen->diagnostics.insert(render(d, &compiled.sources)).second) fresh.push_back(d);
  }
  std::fputs(frontend::render_diagnostics(fresh, &compiled.sources).c_str(), stderr);
  if (!compiled.ok) return kExitBadInput;
  // A copy: the proof adds what the runtime must enforce of it (apply_list_bounds), as `arbc
  // build` and `arbc run` do: a test's run drops a list longer than the proof covers (bad-value).
  lower::LoweredApp lowered = *compiled.lowered;
  if (!no_verify) {
    std::error_code ec;
    std::string app_spec = fs::weakly_canonical(lowered.app.spec_file, ec).string();
    if (ec) app_spec = lowered.app.spec_file;
    auto [gate, first] = seen->gates.try_emplace(app_spec);
    if (first) {
      gate->second = verify_before_writing(
          lowered.app, spec, &compiled.sources, false,
          "no test was run (fix the spec, or run the tests anyway with --no-verify)", "arbc test");
    } else if (!gate->second.pass) {
      std::fprintf(stderr,
                   "arbc test: %s: no test was run: it tests %s, whose proof failed above (fix "
                   "the spec, or run the tests anyway with --no-verify)\n",
                   spec.c_str(), lowered.app.spec_file.c_str());
    }
    if (!gate->second.pass) return gate->second.exit_code;
    apply_list_bounds(gate->second, lowered.app);
  }
  std::string pattern = (fs::temp_directory_path() / "arbc-test-XXXXXX").string();
  if (!mkdtemp(pattern.data())) {
    std::fprintf(stderr, "arbc test: %s: cannot generate the monitors\n", spec.c_str());
    return kExitRuntimeFailure;
  }
  scratch->path = pattern;
  harness::TestApp ready = harness::write_test_app(lowered, pattern);
  if (ready.generate_failed) {
    std::fprintf(stderr, "arbc test: %s: cannot generate the monitors\n", spec.c_str());
    return kExitRuntimeFailure;
  }
  if (!ready.app_json.loc.file.empty()) {
    SourceCache sources;  // as `arbc run` and `arbc verify` show it
    std::fputs(render(ready.app_json, &sources).c_str(), stderr);
    return kExitRuntimeFailure;
  }
  if (!ready.ok) {
    std::istringstream lines(ready.error);
    for (std::string line; std::getline(lines, line);)
      std::fprintf(stderr, "arbc test: %s\n", line.c_str());
    return kExitRuntimeFailure;
  }
  *app_dir = ready.dir;
  *app = std::move(ready.app);
  *tests = lowered.tests;
  return kExitOk;
}

// Runs `tests` on `jobs` threads (1: this one); outcomes in the tests' order.
std::vector<harness::TestOutcome> run_all(const model::App& app, const std::string& dir,
                                          const std::vector<const model::TestCase*>& tests,
                                          unsigned jobs, harness::RuntimeChecks checks) {
  std::vector<harness::TestOutcome> out(tests.size());
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i = next++; i < tests.size(); i = next++)
      out[i] = harness::run_test_case(app, dir, *tests[i], checks);
  };
  std::vector<std::thread> threads;
  for (unsigned k = 1; k < jobs; ++k) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  return out;
}

unsigned jobs_for(size_t tests, unsigned asked) {
  if (asked) return asked;
  unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return tests >= 32 ? cores : 1;  // a thread costs more than a few short tests
}

std::optional<int> parse_args(std::span<char*> args, TestArgs& a) {
  CLI::App cli{"Run the `test` declarations of specs on the embedded runtime, in simulated time",
               "arbc test"};
  cli.add_option("SPEC", a.specs, "spec files with tests")->required();
  std::vector<std::string> msg_path;
  add_msg_path_option(cli, &msg_path);
  cli.add_option("--filter", a.filter, "run only the tests whose name matches GLOB (default *)")
      ->type_name("GLOB");
  cli.add_option("--junit", a.junit, "write JUnit XML of the results to FILE");
  cli.add_flag("--no-verify", a.no_verify, "run the tests without proving the spec first");
  cli.add_option("--jobs", a.jobs,
                 "threads (default: one per core when there are 32 tests or more)");
  cli.add_option("--runtime-checks", a.runtime_checks,
                 "what a test whose run breaks a claim or assumption of the proof does: fail "
                 "(default), warn (said, the test's verdict kept) or off")
      ->check(CLI::IsMember({"fail", "warn", "off"}));
  try {
    cli.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return exit_for_parse_error(cli, e);
  }
  return std::nullopt;
}

// Prints one line per test and each failure's details; returns how many failed.
size_t print_outcomes(const std::string& spec, const std::vector<harness::TestOutcome>& outcomes) {
  size_t failed = 0;
  for (const harness::TestOutcome& t : outcomes) {
    std::printf("%s  %s: %s\n", t.passed ? "PASS" : "FAIL", spec.c_str(), t.name.c_str());
    if (!t.passed) {
      ++failed;
      std::fputs(t.detail.c_str(), stdout);
    }
    std::fputs(t.warnings.c_str(), stdout);
  }
  return failed;
}

}  // namespace

int test_command(std::span<char*> args) {
  TestArgs a;
  if (std::optional<int> exit = parse_args(args, a)) return *exit;
  // Every spec is compiled and proved before any test runs: a spec with an error stops the
  // whole run, so its errors are never followed by PASS lines of the others that could be
  // taken for a result.
  std::vector<std::unique_ptr<PreparedSpec>> prepared;
  std::vector<std::string> not_ready;
  Seen seen;
  int exit = kExitOk;
  for (const std::string& spec : a.specs) {
    auto p = std::make_unique<PreparedSpec>();
    p->spec = spec;
    int rc = prepare_spec(spec, a.no_verify, &seen, &p->scratch, &p->dir, &p->app, &p->tests);
    if (rc != kExitOk) {
      if (exit == kExitOk) exit = rc;
      not_ready.push_back(spec);
      continue;
    }
    prepared.push_back(std::move(p));
  }
  if (exit != kExitOk) {
    if (a.specs.size() > 1) {
      std::fprintf(stderr, "arbc test: no test was run, because of %s (see above)\n",
                   join(not_ready, ", ", " and ").c_str());
    }
    return exit;
  }
  // A filter that chooses none of the declared tests is bad input, not an empty success.
  std::vector<std::string> declared;
  bool any_chosen = false;
  for (const std::unique_ptr<PreparedSpec>& p : prepared) {
    for (const model::TestCase& t : p->tests) {
      declared.push_back(t.name);
      any_chosen = any_chosen || harness::filter_matches(a.filter, t.name);
    }
  }
  if (!declared.empty() && !any_chosen) {
    std::fprintf(stderr, "arbc test: error: %s\n",
                 harness::filter_matched_none(a.filter, declared).c_str());
    return kExitBadInput;
  }
  std::vector<harness::SuiteOutcome> suites;
  size_t total = 0, failed = 0;
  for (const std::unique_ptr<PreparedSpec>& p : prepared) {
    std::vector<const model::TestCase*> chosen;
    for (const model::TestCase& t : p->tests) {
      if (harness::filter_matches(a.filter, t.name)) chosen.push_back(&t);
    }
    std::vector<harness::TestOutcome> outcomes =
        run_all(p->app, p->dir, chosen, jobs_for(chosen.size(), a.jobs),
                a.runtime_checks == "off"    ? harness::RuntimeChecks::Off
                : a.runtime_checks == "warn" ? harness::RuntimeChecks::Warn
                                             : harness::RuntimeChecks::Fail);
    failed += print_outcomes(p->spec, outcomes);
    total += outcomes.size();
    suites.push_back({p->spec, p->app.name, std::move(outcomes)});
  }
  if (!a.junit.empty()) {
    std::ofstream out(a.junit);
    out << harness::junit_xml(suites);
    if (!out) {
      std::fprintf(stderr, "arbc test: error: cannot write %s\n", a.junit.c_str());
      return kExitBadInput;
    }
  }
  std::printf("%zu test%s, %zu passed, %zu failed\n", total, total == 1 ? "" : "s", total - failed,
              failed);
  if (total == 0)
    std::printf("no test declared (a spec declares them as `test \"name\" { ... }`)\n");
  return failed ? kExitRefuted : kExitOk;
}

}  // namespace arbc::cli
