// Code actions: a quick fix for each diagnostic in the range whose note says
// "did you mean 'X'?": replace the diagnostic's range (the misspelt name) with X.
#include "lsp/features.h"
#include "lsp/lsp_diagnostics.h"

namespace arbc::lsp {

namespace {

bool before(Position x, Position y) {
  return x.line < y.line || (x.line == y.line && x.character < y.character);
}

// Whether two LSP ranges overlap. `client` comes from the request: a part it lacks reads as
// the start of the text (parse_position), never as a missing key.
bool overlaps(const nlohmann::json& ours, const nlohmann::json& client) {
  auto position = [](const nlohmann::json& range, const char* which) {
    return range.is_object() ? parse_position(range.value(which, nlohmann::json::object()))
                             : Position{};
  };
  return !before(position(ours, "end"), position(client, "start")) &&
         !before(position(client, "end"), position(ours, "start"));
}

}  // namespace

nlohmann::json code_actions(const Document& doc, const nlohmann::json& range) {
  nlohmann::json out = nlohmann::json::array();
  if (!doc.analysis || doc.analysis->text != doc.text) return out;  // ranges would be stale
  for (const Diagnostic& d : doc.analysis->diagnostics) {
    std::optional<std::string> fix = suggested_fix(d);
    if (!fix || d.loc.line <= 0) continue;
    nlohmann::json diagnostic = diagnostic_json(d, doc.text, doc.uri);
    if (!diagnostic.contains("data")) continue;  // in another file: no name here to replace
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
