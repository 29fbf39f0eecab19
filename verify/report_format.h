// Writers for `arbc verify --format text|json|sarif`. Each takes the reports of all inputs of
// one run. Without `stats` the output has no timings, so golden tests can pin it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/diagnostic.h"
#include "verify/report.h"

namespace arbc::verify {

struct InputReport {
  InputReport(std::string input, VerifyReport report, std::vector<Diagnostic> errors = {})
      : input(std::move(input)), report(std::move(report)), errors(std::move(errors)) {}
  std::string input;  // the file given on the command line
  VerifyReport report;
  // Bad input (a spec with errors, an app.json that does not load): what is wrong. Such an
  // input was not verified (`report` is empty); its verdict is "error", never "proved".
  std::vector<Diagnostic> errors;
  // A spec that was verified: the front end's warnings about it (`lapsing-permission`), printed
  // on stderr as it loaded, carried into every format and counted in the summary.
  std::vector<Diagnostic> warnings;
  bool bad_input() const { return !errors.empty(); }
};

// Compiler-style text: per port what was proved, or the findings with the spec lines quoted
// from `sources` (may be null), then a summary line. Bad inputs are left out (their diagnostics
// went to stderr) but counted in the summary, whose verdict is then "error".
std::string format_text(const std::vector<InputReport>& inputs, SourceCache* sources, bool stats);

// The JSON document described in docs/verify-json.md (a bad input: verdict "error" and its
// diagnostics).
std::string format_json(const std::vector<InputReport>& inputs, bool stats);

// SARIF 2.1.0: one result per finding, ruleId = check id, help at docs/checks.md#<id>; a bad
// input's diagnostics are results too (ruleId = diagnostic id, level error).
std::string format_sarif(const std::vector<InputReport>& inputs, const std::string& tool_version);

}  // namespace arbc::verify

namespace arbc::verify {

// The message counterexamples of a finding: [{source, value, replay}], for JSON and SARIF.
nlohmann::ordered_json messages_json(const std::vector<MessageExample>& messages);

}  // namespace arbc::verify
