// `arbc run DIR|SPEC [--plugin LIB]... [--scenario NAME] [--duration D] [--realtime]
//                    [--seed N] [--trace FILE] [--report FILE.html] [--no-verify]`
// Runs a built application on the embedded runtime (docs/runtime.md), prints the
// per-connection counters and the environment's verdict. Exit: 0 success, 2 bad input,
// 3 run-time failure (the environment reports failure, or, with no environment, a connection
// was quarantined). The app is proved first, unless --no-verify (said in the output and the
// report): a SPEC is built and verified into a temporary directory by `arbc build`, a DIR is
// verified here; a refuted or unknown proof exits 1, and nothing runs. A DIR whose monitors
// differ from the digests in its app.json is bad input. --report writes an HTML page about the
// run (cli/report/run_report.h) from the trace records kept in memory.
#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/report/report_file.h"
#include "cli/report/run_report.h"
#include "cli/verify_gate.h"
#include "core/diagnostic.h"
#include "runtime/app_loader.h"
#include "runtime/runtime.h"

namespace arbc::cli {

namespace {

namespace fs = std::filesystem;

// "60", "60s", "500ms", "2min" -> seconds; false on anything else.
bool parse_duration(const std::string& text, double* seconds) {
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (...) {
    return false;
  }
  std::string unit = text.substr(used);
  double scale = unit.empty() || unit == "s" ? 1 : unit == "ms" ? 1e-3 : unit == "min" ? 60 : -1;
  if (scale < 0 || !(value > 0)) return false;
  *seconds = value * scale;
  return true;
}

// A temporary directory removed when the run ends.
struct TempDir {
  std::string path;
  ~TempDir() {
    std::error_code ignored;
    if (!path.empty()) fs::remove_all(path, ignored);
  }
};

// Builds (and, unless no_verify, verifies) a spec into `temp` with `arbc build`, and returns
// the app directory it wrote. Returns the build's exit code on failure (1 refuted, 2 bad
// input; its diagnostics are already printed).
int build_spec(const std::string& spec, bool no_verify, TempDir* temp, std::string* dir) {
  std::string pattern = (fs::temp_directory_path() / "arbc-run-XXXXXX").string();
  if (!mkdtemp(pattern.data())) {
    std::fprintf(stderr, "arbc run: error: cannot create a temporary directory for the build\n");
    return kExitRuntimeFailure;
  }
  temp->path = pattern;
  std::vector<std::string> words = {"build", spec, "-o", temp->path};
  if (no_verify) words.push_back("--no-verify");
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  int rc = build_command(std::span<char*>(argv.data(), argv.size()));
  if (rc != kExitOk) return rc;
  for (const fs::directory_entry& entry : fs::directory_iterator(temp->path)) {
    if (fs::exists(entry.path() / "app.json")) {
      *dir = entry.path().string();
      return kExitOk;
    }
  }
  std::fprintf(stderr, "arbc run: error: `arbc build %s` wrote no app directory\n", spec.c_str());
  return kExitRuntimeFailure;
}

// Turns the command's input into a built app directory: a directory is used as is, a spec is
// built first. Returns an exit code (kExitOk: *dir is ready).
int prepare_app_dir(const std::string& input, bool no_verify, TempDir* temp, std::string* dir) {
  if (fs::is_directory(input)) {
    *dir = input;
    return kExitOk;
  }
  if (fs::path(input).extension() == ".spec") return build_spec(input, no_verify, temp, dir);
  std::fprintf(stderr,
               "arbc run: error: %s: not an app directory (one with app.json and monitors/, "
               "written by `arbc build`) nor a .spec file\n",
               input.c_str());
  return kExitBadInput;
}

// Ctrl-C ends the run cleanly (counters, summary, trace) instead of killing it.
std::atomic<bool> interrupted{false};

void on_interrupt(int) { interrupted = true; }

void watch_for_interrupt(Runtime& runtime, double period) {
  runtime.executor().post(runtime.now() + period, [&runtime, period] {
    if (interrupted) {
      runtime.executor().stop();
      return;
    }
    watch_for_interrupt(runtime, period);
  });
}

void print_errors(const std::vector<std::string>& errors) {
  for (const std::string& e : errors) std::fprintf(stderr, "arbc run: error: %s\n", e.c_str());
}

// Proves the app before it runs, as `arbc build` does, and sets *proof to what the output and
// the report say about it (a spec was proved when it was built, and the build's summary said
// so). Returns an exit code: kExitOk to run, else the proof's (1 refuted or unknown, 2 a
// malformed model).
int prove_app_dir(const model::App& app, const std::string& dir, bool built_from_spec,
                  bool no_verify, std::string* proof) {
  if (no_verify) {
    *proof = "not verified (--no-verify)";
  } else if (built_from_spec) {
    *proof = verified_summary(app.arbitrated_ports.size());
  } else {
    SourceCache sources;
    VerifyGate gate = verify_before_writing(
        app, (fs::path(dir) / "app.json").string(), &sources, /*strict=*/false,
        "nothing was run (fix the spec and rebuild, or run anyway with --no-verify)", "arbc run");
    if (!gate.pass) return gate.exit_code;
    *proof = gate.summary;
  }
  if (!built_from_spec) std::printf("%s\n", proof->c_str());
  return kExitOk;
}

// The report's input: the header as `arbc run` prints it, the counters, the trace records.
report::RunReportInput report_input(const model::App& app, Runtime& runtime,
                                    const RunOptions& options, bool success,
                                    const std::string& verdict, const std::string& proof,
                                    const std::vector<TraceRecord>& records) {
  report::RunReportInput input;
  report::RunHeader& h = input.header;
  h.app = app.name;
  h.proof = proof;
  h.description = app.description;
  h.scenario = runtime.scenario();
  h.seed = options.seed;
  h.realtime = options.realtime;
  h.requested = options.duration;
  h.end = runtime.now();
  h.stop_reason = runtime.stop_reason();
  h.success = success;
  h.verdict = verdict;
  if (Environment* env = runtime.environment()) h.environment = env->summary();
  std::vector<ConnectionStats> stats = runtime.stats();  // in the app's connection order
  for (size_t i = 0; i < stats.size() && i < app.connections.size(); ++i) {
    const model::Connection& c = app.connections[i];
    input.connections.push_back(
        {stats[i], c.kind == model::ConnectionKind::Feed, c.constraint.to_string()});
  }
  input.records = &records;
  return input;
}

}  // namespace

int run_command(std::span<char*> args) {
  CLI::App cli{"Run a built application on the embedded runtime", "arbc run"};
  std::string input, duration_text = "60s";
  std::vector<std::string> plugins;
  bool no_verify = false;
  RunOptions options;
  cli.add_option("app", input, "an app directory written by `arbc build` (or a .spec)")->required();
  cli.add_option("--plugin", plugins, "a shared library with modules (repeatable)");
  cli.add_option("--scenario", options.scenario, "scenario name passed to the environment");
  cli.add_option("--duration", duration_text, "how long to run: 60s, 500ms, 2min (default 60s)");
  cli.add_flag("--no-verify", no_verify,
               "run without the proof (a SPEC is built without it, a DIR is not verified)");
  cli.add_flag("--realtime", options.realtime, "run on the wall clock instead of simulated time");
  cli.add_option("--seed", options.seed, "seed of every random generator (default 1)");
  cli.add_option("--trace", options.trace_path, "write a JSON-lines trace to FILE");
  std::string report_path;
  cli.add_option("--report", report_path, "write a self-contained HTML report of the run to FILE");
  try {
    cli.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    int rc = cli.exit(e);
    return rc == 0 ? kExitOk : kExitBadInput;
  }
  if (!parse_duration(duration_text, &options.duration)) {
    std::fprintf(stderr,
                 "arbc run: error: --duration '%s' is not a positive duration such as 60s, "
                 "500ms or 2min\n",
                 duration_text.c_str());
    return kExitBadInput;
  }

  for (const std::string& lib : plugins) {
    std::string error = load_plugin(lib);
    if (!error.empty()) {
      print_errors({lib + ": " + error});
      return kExitBadInput;
    }
  }
  print_errors(Registry::global().errors());

  std::string dir, error;
  TempDir temp;
  int prepared = prepare_app_dir(input, no_verify, &temp, &dir);
  if (prepared != kExitOk) return prepared;
  AppDirLoad load = load_app_dir(dir);
  if (!load.ok) {
    print_errors(load.errors);
    return kExitBadInput;
  }
  std::vector<std::string> mismatches =
      check_modules(load.app, (fs::path(dir) / "app.json").string());
  if (!mismatches.empty()) {
    print_errors(mismatches);
    return kExitBadInput;
  }
  std::string proof;
  int proved =
      prove_app_dir(load.app, dir, /*built_from_spec=*/!temp.path.empty(), no_verify, &proof);
  if (proved != kExitOk) return proved;
  std::vector<TraceRecord> records;  // the whole trace in memory, for --report
  if (!report_path.empty()) options.trace_records = &records;
  std::unique_ptr<Runtime> runtime = Runtime::create(load.app, dir, options, &error);
  if (!runtime) {
    print_errors({(fs::path(dir) / "app.json").string() + ": " + error});
    return kExitBadInput;
  }
  report::ReportFile report_file;
  if (!report_path.empty()) {
    std::string open_error = report_file.open(report_path);
    if (!open_error.empty()) {
      print_errors({open_error});
      return kExitBadInput;
    }
  }

  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  watch_for_interrupt(*runtime, options.realtime ? 0.05 : 1.0);
  runtime->run();
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  if (interrupted) std::fputs("arbc run: interrupted\n", stderr);

  std::printf("app %s, scenario %s, seed %llu, %s time %.3f s%s%s\n", load.app.name.c_str(),
              runtime->scenario().c_str(), static_cast<unsigned long long>(options.seed),
              options.realtime ? "real" : "simulated", runtime->now(),
              runtime->stopped_early() ? ", stopped: " : "", runtime->stop_reason().c_str());
  std::fputs(runtime->stats_table().c_str(), stdout);
  bool success = true;
  std::string verdict;
  if (Environment* env = runtime->environment()) {
    std::string summary = env->summary();
    if (!summary.empty()) {
      std::fputs(summary.c_str(), stdout);
      if (summary.back() != '\n') std::fputc('\n', stdout);
    }
    success = env->success();
    verdict = success ? "success" : "failure";
  } else {
    for (const ConnectionStats& s : runtime->stats()) success &= !s.quarantined;
    verdict = std::string(success ? "success" : "failure") +
              " (no environment; judged by quarantined connections)";
  }
  std::printf("result: %s\n", verdict.c_str());
  if (!report_path.empty()) {
    report::RunReportInput input =
        report_input(load.app, *runtime, options, success, verdict, proof, records);
    if (interrupted && input.header.stop_reason.empty()) input.header.stop_reason = "interrupted";
    std::string html = report::render_run_report(input);
    std::string write_error = report_file.write(html);
    if (!write_error.empty()) {
      print_errors({write_error});
      return kExitRuntimeFailure;
    }
    std::printf("report: %s (%zu bytes)\n", report_path.c_str(), html.size());
  }
  return success ? kExitOk : kExitRuntimeFailure;
}

}  // namespace arbc::cli
