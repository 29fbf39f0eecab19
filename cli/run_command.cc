// `arbc run DIR|SPEC [--plugin LIB]... [--scenario NAME] [--duration D] [--realtime]
//                    [--seed N] [--trace FILE]`
// Runs a built application on the embedded runtime (DESIGN.md sections 7, 8), prints the
// per-connection counters and the environment's verdict. Exit: 0 success, 2 bad input,
// 3 run-time failure (the environment reports failure, or, with no environment, a connection
// was quarantined).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/commands.h"
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

// Turns the command's input into a built app directory. A directory is used as is. A spec
// must first be built (and verified unless --no-verify) into a temporary directory; that
// needs the compiler stage, which is added here once it exists.
bool prepare_app_dir(const std::string& input, std::string* dir, std::string* error) {
  if (fs::is_directory(input)) {
    *dir = input;
    return true;
  }
  if (fs::path(input).extension() == ".spec") {
    *error = input +
             ": running a spec directly needs `arbc build`, which this build of arbc does not "
             "have yet; build it with `arbc build " +
             input + " -o OUT` and run OUT/<app>";
    return false;
  }
  *error = input +
           ": not an app directory (one with app.json and monitors/, written by "
           "`arbc build`) nor a .spec file";
  return false;
}

void print_errors(const std::vector<std::string>& errors) {
  for (const std::string& e : errors) std::fprintf(stderr, "arbc run: error: %s\n", e.c_str());
}

}  // namespace

int run_command(std::span<char*> args) {
  CLI::App cli{"Run a built application on the embedded runtime", "arbc run"};
  std::string input, duration_text = "60s";
  std::vector<std::string> plugins;
  RunOptions options;
  cli.add_option("app", input, "an app directory written by `arbc build` (or a .spec)")->required();
  cli.add_option("--plugin", plugins, "a shared library with modules (repeatable)");
  cli.add_option("--scenario", options.scenario, "scenario name passed to the environment");
  cli.add_option("--duration", duration_text, "how long to run: 60s, 500ms, 2min (default 60s)");
  cli.add_flag("--realtime", options.realtime, "run on the wall clock instead of simulated time");
  cli.add_option("--seed", options.seed, "seed of every random generator (default 1)");
  cli.add_option("--trace", options.trace_path, "write a JSON-lines trace to FILE");
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
  if (!prepare_app_dir(input, &dir, &error)) {
    print_errors({error});
    return kExitBadInput;
  }
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
  std::unique_ptr<Runtime> runtime = Runtime::create(load.app, dir, options, &error);
  if (!runtime) {
    print_errors({(fs::path(dir) / "app.json").string() + ": " + error});
    return kExitBadInput;
  }

  runtime->run();

  std::printf("app %s, scenario %s, seed %llu, %s time %.3f s%s%s\n", load.app.name.c_str(),
              runtime->scenario().c_str(), static_cast<unsigned long long>(options.seed),
              options.realtime ? "real" : "simulated", runtime->now(),
              runtime->stopped_early() ? ", stopped: " : "", runtime->stop_reason().c_str());
  std::fputs(runtime->stats_table().c_str(), stdout);
  bool success = true;
  if (Environment* env = runtime->environment()) {
    std::string summary = env->summary();
    if (!summary.empty()) {
      std::fputs(summary.c_str(), stdout);
      if (summary.back() != '\n') std::fputc('\n', stdout);
    }
    success = env->success();
    std::printf("result: %s\n", success ? "success" : "failure");
  } else {
    for (const ConnectionStats& s : runtime->stats()) success &= !s.quarantined;
    std::printf("result: %s (no environment; judged by quarantined connections)\n",
                success ? "success" : "failure");
  }
  return success ? kExitOk : kExitRuntimeFailure;
}

}  // namespace arbc::cli
