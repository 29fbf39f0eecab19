#include "lsp/lookup.h"

#include "lsp/uri.h"

namespace arbc::lsp {

Lookup look_up(const Document& doc, Position p) {
  Lookup l;
  if (!doc.analysis || !doc.analysis->index) return l;
  l.index = doc.analysis->index.get();
  std::tie(l.line, l.column) = arbc_position(doc.text, p);
  l.occurrence = l.index->occurrence_at(l.line, l.column);
  if (l.occurrence) l.symbol = &l.index->symbols[l.occurrence->symbol];
  return l;
}

bool in_app_spec(const Document& doc, const Loc& loc) {
  return doc.analysis && !doc.analysis->app_file.empty() && loc.file == doc.analysis->app_file &&
         loc.file != doc.path;
}

// The text `loc` is in: the document's last text that parsed, or a tests file's app spec.
std::string_view text_of(const Document& doc, const Loc& loc) {
  if (!doc.analysis) return doc.text;
  return in_app_spec(doc, loc) ? doc.analysis->app_text : doc.analysis->index_text;
}

nlohmann::json index_range(const Document& doc, const Loc& loc) {
  return range_json(text_of(doc, loc), loc);
}

nlohmann::json location_json(const Document& doc, const Loc& loc) {
  return {{"uri", in_app_spec(doc, loc) ? path_to_uri(loc.file) : doc.uri},
          {"range", index_range(doc, loc)}};
}

std::string source_text(const Document& doc, const Loc& loc) {
  if (!doc.analysis || loc.line <= 0) return "";
  std::string_view text = text_of(doc, loc);
  int end_line = loc.end_line > 0 ? loc.end_line : loc.line;
  int end_column = loc.end_line > 0 ? loc.end_column : loc.column + 1;
  size_t begin = offset_of(text, lsp_position(text, loc.line, loc.column));
  size_t end = offset_of(text, lsp_position(text, end_line, end_column));
  return end > begin ? std::string(text.substr(begin, end - begin)) : "";
}

}  // namespace arbc::lsp
