// Writers for `arbc verify --format text|json|sarif`. Each takes the reports of all inputs of
// one run. Without `stats` the output has no timings, so golden tests can pin it.
#pragma once

#include <string>
#include <vector>

#include "core/diagnostic.h"
#include "verify/report.h"

namespace arbc::verify {

struct InputReport {
  std::string input;  // the file given on the command line
  VerifyReport report;
};

// Compiler-style text: per port what was proved, or the findings with the spec lines quoted
// from `sources` (may be null), then a summary line.
std::string format_text(const std::vector<InputReport>& inputs, SourceCache* sources, bool stats);

// The JSON document described in docs/verify-json.md.
std::string format_json(const std::vector<InputReport>& inputs, bool stats);

// SARIF 2.1.0: one result per finding, ruleId = check id, help at docs/checks.md#<id>.
std::string format_sarif(const std::vector<InputReport>& inputs, const std::string& tool_version);

}  // namespace arbc::verify
