// `arbc verify [SPEC | APP.json | APP.xml]...`: the proof (docs/design.md#the-proof) on each input.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/counterexample_files.h"
#include "cli/duration_option.h"
#include "cli/msg_path_option.h"
#include "cli/parse_error.h"
#include "core/diagnostic.h"
#include "core/monitor_digests.h"
#include "harness/model_loader.h"
#include "harness/monitor_runner.h"
#include "harness/test_replayer.h"
#include "import/yarp/yarp_directory.h"
#include "import/yarp/yarp_verify.h"
#include "verify/report_format.h"
#include "verify/verify.h"

namespace arbc::cli {
namespace {

constexpr const char* kDescription =
    "Prove that in no event state can two rules of one arbitrated port be selected, and run the\n"
    "other checks (dead, unfed, unused, ownership, complete, assert; see docs/checks.md).\n"
    "With no inputs, verifies specs/*.spec in the current directory (for pre-commit hooks).\n"
    "An APP.xml is a yarpmanager application with Lua monitors (docs/yarp.md).\n"
    "Exit codes: 0 proved, 1 refuted or unknown, 2 bad input.";

// An app.json (or a directory holding one) is proved together with its monitors: each must
// have the bytes whose SHA-256 it records, or the proof would be about code that does not run.
// Prints one line per changed or missing monitor; true when all match.
bool monitors_match(const std::string& input, const model::App& app) {
  std::error_code ec;
  std::filesystem::path dir = std::filesystem::is_directory(input, ec)
                                  ? std::filesystem::path(input)
                                  : std::filesystem::path(input).parent_path();
  std::vector<std::string> errors = model::check_monitor_files(app, dir.string());
  for (const std::string& e : errors) std::fprintf(stderr, "arbc verify: %s\n", e.c_str());
  return errors.empty();
}

// specs/*.spec under the current directory, sorted so the output is stable.
std::vector<std::string> default_inputs() {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("specs", ec)) {
    if (entry.path().extension() == ".spec") out.push_back(entry.path().generic_string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The command line of `arbc verify`.
struct VerifyArgs {
  std::vector<std::string> inputs;
  std::string format = "text";
  verify::VerifyOptions options;
  bool stats = false;
  std::vector<std::string> yarp_paths;  // --yarp-path: where an APP.xml's monitors are
  std::string counterexamples;          // --counterexamples: where replayed tests are written
  std::vector<std::string> msg_path;    // --msg-path: folders of PKG/msg/NAME.msg (ARBC_MSG_PATH)
};

// Parses `arbc verify`'s arguments into `a`; an exit code when the command ends here (--help,
// a bad option).
std::optional<int> parse_args(std::span<char*> args, VerifyArgs& a) {
  CLI::App cli(kDescription, "arbc verify");
  cli.add_option("inputs", a.inputs,
                 "specs (*.spec), app.json files, `arbc build` directories, or yarpmanager "
                 "application XMLs (*.xml)");
  add_msg_path_option(cli, &a.msg_path);
  cli.add_option("--format", a.format, "output format")
      ->check(CLI::IsMember({"text", "json", "sarif"}))
      ->capture_default_str();
  cli.add_flag("--strict", a.options.strict, "treat warnings (dead, unused) as errors");
  cli.add_option("--timeout", a.options.timeout_seconds,
                 "seconds the solver may spend on all ports of one input (or a time with its "
                 "unit: 2min); a check cut short is unknown, and unknown fails")
      ->transform(seconds_option(false))
      ->type_name("DURATION")
      ->capture_default_str();
  cli.add_option("--max-pairs", a.options.max_pairs_per_port,
                 "overlapping pairs per port reported with a counterexample; the rest are counted")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  cli.add_option(
         "--temporal-bound", a.options.temporal_bound,
         "messages into a port that properties over time (`never`, `only`, `after`, `stable`) are "
         "explored to")
      ->check(CLI::Range(2, 1024))
      ->capture_default_str();
  cli.add_option("--list-bound", a.options.list_bound,
                 "a rule whose body reads list elements at an index it does not know (`xs[i]`, "
                 "`==` of lists) is proved for lists of at most this many elements (its verdict "
                 "says so); bodies that read `len`, constant indexes, `min_by`, `max_by`, "
                 "`min`/`max` of a list are proved for every length")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cli.add_option("--counterexamples", a.counterexamples,
                 "a folder to write each counterexample into, as a tests file that states the "
                 "claim it breaks: a property over time (APP.RULE.test.spec), a port's "
                 "exclusivity (APP.M_p.RULE.RULE.exclusive.test.spec), an assert over events "
                 "or over `emitted` (APP.M_p.RULE.assert.test.spec), a resource "
                 "(APP.NAME.RULE.RULE.resource.test.spec); `arbc test` of it fails until the app "
                 "is fixed. One a test cannot replay is written as a .txt that says why. A second "
                 "counterexample with the same name (two spacings of one "
                 "rule) gets `2`, `3`, ... appended (APP.RULE2.test.spec), never overwriting the "
                 "first");
  cli.add_flag("--stats", a.stats, "add timings and solver query counts");
  cli.add_option("--yarp-path", a.yarp_paths,
                 "a folder to search for the Lua monitors an APP.xml's carriers name (repeatable)");
  try {
    cli.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return exit_for_parse_error(cli, e);
  }
  return std::nullopt;
}

// A disagreement between Z3 and the runtime is a bug: say so on stderr whatever the format.
void print_internal_errors(const std::vector<verify::InputReport>& reports) {
  auto print = [](const std::vector<verify::Finding>& findings) {
    for (const verify::Finding& f : findings)
      if (f.check == verify::kCheckInternal)
        std::fprintf(stderr, "arbc verify: %s\n", f.message.c_str());
  };
  for (const verify::InputReport& r : reports) {
    for (const verify::PortResult& p : r.report.ports) print(p.findings);
    for (const verify::ResourceResult& res : r.report.resources) print(res.findings);
    print(r.report.app_findings);
  }
}

// A directory without app.json: a --target yarp build stands for its application XML, and a
// folder of yarpmanager XMLs is bad input that names them. False when `input` goes no further.
bool resolve_yarp_directory(std::string& input, std::vector<verify::InputReport>& reports) {
  yarp::YarpDirectory dir = yarp::yarp_directory(input);
  if (dir.build_xml) input = *dir.build_xml;
  if (dir.build_xml || dir.xmls.empty()) return true;
  std::string xmls;
  for (const std::string& x : dir.xmls) xmls += (xmls.empty() ? "" : ", ") + x;
  std::string error = input + ": a directory without app.json, holding " + xmls +
                      "; give the yarpmanager application XML itself (arbc verify " + dir.xmls[0] +
                      ")";
  std::fprintf(stderr, "arbc verify: %s\n", error.c_str());
  reports.push_back(
      {input, {}, {harness::file_error(input, error.substr(input.size() + 2), diag::Io)}});
  return false;
}

// Writes the reports as --format asks; the exit code of the whole command.
int finish(const VerifyArgs& a, const std::vector<verify::InputReport>& reports, bool bad_input) {
  print_internal_errors(reports);
  if (!a.counterexamples.empty() && !write_counterexamples(reports, a.counterexamples))
    return kExitRuntimeFailure;
  std::string out;
  if (a.format == "json") {
    out = verify::format_json(reports, a.stats);
  } else if (a.format == "sarif") {
    out = verify::format_sarif(reports, ARBC_VERSION);
  } else if (std::any_of(reports.begin(), reports.end(),
                         [](const verify::InputReport& r) { return !r.bad_input(); })) {
    SourceCache sources;
    out = verify::format_text(reports, &sources, a.stats);
  }
  std::fputs(out.c_str(), stdout);

  if (bad_input) return kExitBadInput;
  for (const verify::InputReport& r : reports) {
    if (r.report.verdict != verify::Verdict::Proved) return kExitRefuted;
  }
  return kExitOk;
}

// --counterexamples names a folder, made if missing: a file there, or a folder that cannot be
// made, is bad input, said before the proof runs (it said so after, with exit 3).
bool counterexample_folder_ok(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
    std::fprintf(stderr,
                 "arbc verify: --counterexamples %s: not a folder; give a folder to write the "
                 "tests files into (it is made if missing)\n",
                 dir.c_str());
    return false;
  }
  if (!fs::create_directories(dir, ec) && ec) {
    std::fprintf(stderr, "arbc verify: --counterexamples %s: cannot make the folder: %s\n",
                 dir.c_str(), ec.message().c_str());
    return false;
  }
  return true;
}

}  // namespace

int verify_command(std::span<char*> args) {
  VerifyArgs a;
  if (std::optional<int> exit = parse_args(args, a)) return *exit;
  if (!a.counterexamples.empty() && !counterexample_folder_ok(a.counterexamples))
    return kExitBadInput;
  std::vector<std::string>& inputs = a.inputs;
  if (inputs.empty() && (inputs = default_inputs()).empty()) {
    std::fputs(
        "arbc verify: no inputs, and no specs/*.spec in the current directory; give "
        "specs or app.json files (arbc verify --help)\n",
        stderr);
    return kExitBadInput;
  }

  bool bad_input = false;
  std::vector<verify::InputReport> reports;
  for (std::string input : inputs) {
    if (!resolve_yarp_directory(input, reports)) {
      bad_input = true;
      continue;
    }
    if (yarp::is_yarp_application(input)) {
      yarp::YarpVerify y = yarp::verify_yarp_application(input, a.options, a.yarp_paths);
      std::fputs(y.diagnostics.c_str(), stderr);
      bad_input |= !y.ok;
      if (y.ok) reports.push_back({input, std::move(y.report)});
      continue;
    }
    harness::LoadNotes notes;
    std::string error;
    std::optional<model::App> app = harness::load_model(input, &notes, &error);
    std::fputs(notes.rendered.c_str(), stderr);
    if (!app) {
      std::fprintf(stderr, "arbc verify: %s\n", error.c_str());
      if (notes.errors.empty())
        notes.errors.push_back(harness::file_error(input, error, diag::AppJson));
      reports.push_back({input, {}, std::move(notes.errors)});
      bad_input = true;
      continue;
    }
    if (!harness::is_spec_path(input) && !monitors_match(input, *app)) {
      bad_input = true;
      continue;
    }
    harness::LuaMonitorRunner runner(input, *app);
    verify::VerifyOptions options = a.options;
    options.runner = &runner;
    harness::RuntimeTestReplayer replayer(input);
    options.test_replayer = &replayer;
    options.on_stuck = [&a, &reports, &app, &input, bad_input] {
      std::vector<verify::InputReport> all = reports;  // what is done, and this input unknown
      all.push_back({input, verify::stuck_report(*app, a.options.timeout_seconds)});
      int code = finish(a, all, bad_input);
      std::fflush(stdout);
      std::_Exit(code);  // the main thread is inside Z3 and cannot be ended otherwise
    };
    std::optional<verify::VerifyReport> report = verify::verify_app(*app, options, &error);
    if (!report) {
      std::fprintf(stderr, "arbc verify: %s: %s\n", input.c_str(), error.c_str());
      reports.push_back({input, {}, {harness::file_error(input, error, diag::AppJson)}});
      bad_input = true;
      continue;
    }
    reports.push_back({input, std::move(*report)});
    reports.back().warnings = std::move(notes.warnings);
  }

  return finish(a, reports, bad_input);
}

}  // namespace arbc::cli
