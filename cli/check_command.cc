// `arbc check SPEC... [--format text|json]`: parse and semantic checks (docs/cli.md#arbc-check).
// Exit 0 when every spec is fine, 2 when any has an error. Text diagnostics go to stderr,
// JSON to stdout.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/left_at_exit.h"
#include "cli/msg_path_option.h"
#include "cli/parse_error.h"
#include "compiler/frontend/frontend.h"
#include "compiler/lower/compile_spec.h"
#include "core/check_ids.h"

namespace arbc::cli {

namespace {

nlohmann::json diagnostic_json(const Diagnostic& d) {
  nlohmann::json j = {
      {"severity", severity_name(d.severity)},
      {"message", d.message},
      {"id", d.id},
  };
  if (!d.loc.file.empty()) j["file"] = d.loc.file;
  if (d.loc.line > 0) {
    j["line"] = d.loc.line;
    j["column"] = d.loc.column;
    j["end_line"] = d.loc.end_line;
    j["end_column"] = d.loc.end_column;
  }
  if (!d.notes.empty()) {
    j["notes"] = nlohmann::json::array();
    for (const Diagnostic& note : d.notes) j["notes"].push_back(diagnostic_json(note));
  }
  return j;
}

}  // namespace

int check_command(std::span<char*> args) {
  CLI::App app{
      "Parse and check behaviour specs: syntax, names, types, ports and rules.\n"
      "Exit 0 when every spec is fine, 2 when any has an error."};
  app.name("arbc check");
  std::vector<std::string> specs;
  std::string format = "text";
  bool list_ids = false;
  app.add_option("SPEC", specs, "spec files to check")->type_name("FILE");
  std::vector<std::string> msg_path;
  add_msg_path_option(app, &msg_path);
  app.add_option("--format", format, "text (compiler style, on stderr) or json (on stdout)")
      ->check(CLI::IsMember({"text", "json"}));
  app.add_flag("--list-ids", list_ids,
               "print every diagnostic id arbc can report: id, stage (check, verify, internal), "
               "meaning");
  try {
    app.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return exit_for_parse_error(app, e);
  }
  if (list_ids) {
    for (const frontend::CheckId& id : frontend::all_check_ids())
      std::printf("%-26s %-9s %s\n", std::string(id.id).c_str(), std::string(id.stage).c_str(),
                  std::string(id.meaning).c_str());
    return kExitOk;
  }
  if (specs.empty()) {
    std::fputs("arbc check: name at least one spec file (see arbc check --help)\n", stderr);
    return kExitBadInput;
  }

  bool all_ok = true;
  nlohmann::json report = {{"files", nlohmann::json::array()},
                           {"diagnostics", nlohmann::json::array()}};
  for (const std::string& path : specs) {
    // Lowered too: which container an event of a test's `expect` lives in is known only once
    // the feeds are (compiler/lower/test_containers.h), and `check` reports every bad input.
    lower::CompiledSpec result = lower::compile_spec(path);
    all_ok = all_ok && result.ok;
    if (format == "json") {
      size_t errors = 0;
      for (const Diagnostic& d : result.diagnostics) {
        errors += d.severity == Severity::Error;
        report["diagnostics"].push_back(diagnostic_json(d));
      }
      report["files"].push_back({{"file", path}, {"ok", result.ok}, {"errors", errors}});
    } else {
      std::string text = frontend::render_diagnostics(result.diagnostics, &result.sources);
      std::fputs(text.c_str(), stderr);
    }
    if (&path == &specs.back()) leave_at_exit(result);
  }
  if (format == "json") std::cout << report.dump(2) << "\n";
  return all_ok ? kExitOk : kExitBadInput;
}

}  // namespace arbc::cli
