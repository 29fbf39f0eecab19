// `arbc verify [SPEC | APP.json | APP.xml]...`: the proof (docs/design.md#the-proof) on each input.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/model_loader.h"
#include "cli/yarp_verify.h"
#include "core/diagnostic.h"
#include "core/monitor_digests.h"
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

}  // namespace

int verify_command(std::span<char*> args) {
  CLI::App cli(kDescription, "arbc verify");
  std::vector<std::string> inputs;
  std::string format = "text";
  verify::VerifyOptions options;
  bool stats = false;
  std::vector<std::string> yarp_paths;
  cli.add_option("inputs", inputs,
                 "specs (*.spec), app.json files, `arbc build` directories, or yarpmanager "
                 "application XMLs (*.xml)");
  cli.add_option("--format", format, "output format")
      ->check(CLI::IsMember({"text", "json", "sarif"}))
      ->capture_default_str();
  cli.add_flag("--strict", options.strict, "treat warnings (dead, unused) as errors");
  cli.add_option("--timeout", options.timeout_seconds,
                 "seconds the solver may spend on all ports of one input; a check cut short is "
                 "unknown, and unknown fails")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cli.add_option("--max-pairs", options.max_pairs_per_port,
                 "overlapping pairs per port reported with a counterexample; the rest are counted")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  cli.add_flag("--stats", stats, "add timings and solver query counts");
  cli.add_option("--yarp-path", yarp_paths,
                 "a folder to search for the Lua monitors an APP.xml's carriers name (repeatable)");
  try {
    cli.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    int code = cli.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }

  if (inputs.empty()) {
    inputs = default_inputs();
    if (inputs.empty()) {
      std::fputs(
          "arbc verify: no inputs, and no specs/*.spec in the current directory; give "
          "specs or app.json files (arbc verify --help)\n",
          stderr);
      return kExitBadInput;
    }
  }

  bool bad_input = false;
  std::vector<verify::InputReport> reports;
  for (const std::string& input : inputs) {
    if (is_yarp_application(input)) {
      YarpVerify y = verify_yarp_application(input, options, yarp_paths);
      std::fputs(y.diagnostics.c_str(), stderr);
      bad_input |= !y.ok;
      if (y.ok) reports.push_back({input, std::move(y.report)});
      continue;
    }
    ModelLoad load = load_model(input);
    std::fputs(load.diagnostics.c_str(), stderr);
    if (!load.ok) {
      std::fprintf(stderr, "arbc verify: %s\n", load.error.c_str());
      bad_input = true;
      continue;
    }
    if (!load.spec && !monitors_match(input, load.app)) {
      bad_input = true;
      continue;
    }
    verify::VerifyResult result = verify::verify_app(load.app, options);
    if (!result.ok) {
      std::fprintf(stderr, "arbc verify: %s: %s\n", input.c_str(), result.error.c_str());
      bad_input = true;
      continue;
    }
    reports.push_back({input, std::move(result.report)});
  }

  // A disagreement between Z3 and the runtime is a bug: say so on stderr whatever the format.
  for (const verify::InputReport& r : reports) {
    for (const verify::PortResult& p : r.report.ports) {
      for (const verify::Finding& f : p.findings) {
        if (f.check == verify::kCheckInternal) {
          std::fprintf(stderr, "arbc verify: %s\n", f.message.c_str());
        }
      }
    }
  }

  std::string out;
  if (format == "json") {
    out = verify::format_json(reports, stats);
  } else if (format == "sarif") {
    out = verify::format_sarif(reports, ARBC_VERSION);
  } else if (!reports.empty()) {
    SourceCache sources;
    out = verify::format_text(reports, &sources, stats);
  }
  std::fputs(out.c_str(), stdout);

  if (bad_input) return kExitBadInput;
  for (const verify::InputReport& r : reports) {
    if (r.report.verdict != verify::Verdict::Proved) return kExitRefuted;
  }
  return kExitOk;
}

}  // namespace arbc::cli
