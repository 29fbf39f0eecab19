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

nlohmann::json diagnostic_json(const Diagnostic& d, std::string_view text, const std::string& uri) {
  model::SourceLocation at = d.loc;
  if (at.line <= 0) at = {d.loc.file, 1, 1, 1, 1};  // about the whole file: its start
  nlohmann::json j = {{"range", range_json(text, at)},
                      {"severity", lsp_severity(d.severity)},
                      {"source", "arbc"},
                      {"message", d.message}};
  if (!d.id.empty()) j["code"] = d.id;
  nlohmann::json related = nlohmann::json::array();
  for (const Diagnostic& n : d.notes) {
    bool here = n.loc.line > 0 && (n.loc.file.empty() || n.loc.file == d.loc.file);
    bool elsewhere = n.loc.line > 0 && !here;
    nlohmann::json range = range_json(text, here ? n.loc : at);
    if (elsewhere) {  // without that file's text, columns count code points
      int end_line = n.loc.end_line > 0 ? n.loc.end_line : n.loc.line;
      int end_column = n.loc.end_line > 0 ? n.loc.end_column : n.loc.column + 1;
      range = {{"start", position_json({n.loc.line - 1, n.loc.column - 1})},
               {"end", position_json({end_line - 1, end_column - 1})}};
    }
    related.push_back(
        {{"location", {{"uri", elsewhere ? path_to_uri(n.loc.file) : uri}, {"range", range}}},
         {"message", n.message}});
  }
  if (!related.empty()) j["relatedInformation"] = related;
  if (auto fix = suggested_fix(d)) j["data"] = {{"fix", *fix}};
  return j;
}

}  // namespace arbc::lsp
