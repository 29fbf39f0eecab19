#include "lsp/lsp_diagnostics.h"

#include "lsp/positions.h"
#include "lsp/uri.h"

namespace arbc::lsp {

namespace {

int lsp_severity(Severity s) {
  switch (s) {
    case Severity::Error:
      return 1;
    case Severity::Warning:
      return 2;
    case Severity::Note:
      return 3;
  }
  return 1;
}

}  // namespace

std::optional<std::string> suggested_fix(const Diagnostic& d) {
  const std::string prefix = "did you mean '";
  for (const Diagnostic& n : d.notes) {
    const std::string& m = n.message;
    if (m.compare(0, prefix.size(), prefix) != 0 || m.size() < prefix.size() + 3) continue;
    if (m.compare(m.size() - 2, 2, "'?") != 0) continue;
    return m.substr(prefix.size(), m.size() - prefix.size() - 2);
  }
  return std::nullopt;
}

namespace {

// A range in a file whose text we do not have: columns count code points.
nlohmann::json range_elsewhere(const model::SourceLocation& loc) {
  int end_line = loc.end_line > 0 ? loc.end_line : loc.line;
  int end_column = loc.end_line > 0 ? loc.end_column : loc.column + 1;
  return {{"start", position_json({loc.line - 1, loc.column - 1})},
          {"end", position_json({end_line - 1, end_column - 1})}};
}

}  // namespace

nlohmann::json diagnostic_json(const Diagnostic& d, std::string_view text, const std::string& uri) {
  const std::string path = uri_to_path(uri);
  model::SourceLocation at = d.loc;
  std::string message = d.message;
  nlohmann::json related = nlohmann::json::array();
  // In another file (a tests file's app spec, docs/testing.md): shown at the start of this
  // document, saying where, with that place as related information.
  bool moved = at.line > 0 && !at.file.empty() && at.file != path;
  if (moved) {
    message =
        at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " + message;
    related.push_back(
        {{"location", {{"uri", path_to_uri(at.file)}, {"range", range_elsewhere(at)}}},
         {"message", "the error is here"}});
    at.line = 0;
  }
  if (at.line <= 0) at = {d.loc.file, 1, 1, 1, 1};  // about the whole file: its start
  nlohmann::json j = {{"range", range_json(text, at)},
                      {"severity", lsp_severity(d.severity)},
                      {"source", "arbc"},
                      {"message", message}};
  if (!d.id.empty()) j["code"] = d.id;
  for (const Diagnostic& n : d.notes) {
    bool here = n.loc.line > 0 && (n.loc.file.empty() ? !moved : n.loc.file == path);
    bool elsewhere = n.loc.line > 0 && !here;
    related.push_back(
        {{"location",
          {{"uri", elsewhere ? path_to_uri(n.loc.file.empty() ? d.loc.file : n.loc.file) : uri},
           {"range", elsewhere ? range_elsewhere(n.loc) : range_json(text, here ? n.loc : at)}}},
         {"message", n.message}});
  }
  if (!related.empty()) j["relatedInformation"] = related;
  // A fix replaces the diagnostic's range: only where that range is the misspelt name.
  if (auto fix = suggested_fix(d); fix && !moved) j["data"] = {{"fix", *fix}};
  return j;
}

}  // namespace arbc::lsp
