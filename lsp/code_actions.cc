// Code actions: a quick fix for each diagnostic in the range whose note says
// "did you mean 'X'?": replace the diagnostic's range (the misspelt name) with X.
#include "lsp/features.h"
#include "lsp/lsp_diagnostics.h"

namespace arbc::lsp {

namespace {

bool overlaps(const nlohmann::json& a, const nlohmann::json& b) {
  auto before = [](const nlohmann::json& x, const nlohmann::json& y) {  // x < y
    return x["line"].get<int>() < y["line"].get<int>() ||
           (x["line"] == y["line"] && x["character"].get<int>() < y["character"].get<int>());
  };
  return !before(a["end"], b["start"]) && !before(b["end"], a["start"]);
}

}  // namespace

nlohmann::json code_actions(const Document& doc, const nlohmann::json& range) {
  nlohmann::json out = nlohmann::json::array();
  if (!doc.analysis || doc.analysis->text != doc.text) return out;  // ranges would be stale
  for (const Diagnostic& d : doc.analysis->diagnostics) {
    std::optional<std::string> fix = suggested_fix(d);
    if (!fix || d.loc.line <= 0) continue;
    nlohmann::json diagnostic = diagnostic_json(d, doc.text, doc.uri);
    if (!overlaps(diagnostic["range"], range)) continue;
    nlohmann::json edit = {{"range", diagnostic["range"]}, {"newText", *fix}};
    out.push_back({{"title", "Change to '" + *fix + "'"},
                   {"kind", "quickfix"},
                   {"isPreferred", true},
                   {"diagnostics", nlohmann::json::array({diagnostic})},
                   {"edit", {{"changes", {{doc.uri, nlohmann::json::array({edit})}}}}}});
  }
  return out;
}

}  // namespace arbc::lsp
