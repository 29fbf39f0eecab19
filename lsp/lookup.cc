#include "lsp/lookup.h"

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

nlohmann::json index_range(const Document& doc, const Loc& loc) {
  return range_json(doc.analysis ? std::string_view(doc.analysis->index_text) : doc.text, loc);
}

nlohmann::json location_json(const Document& doc, const Loc& loc) {
  return {{"uri", doc.uri}, {"range", index_range(doc, loc)}};
}

std::string source_text(const Document& doc, const Loc& loc) {
  if (!doc.analysis || loc.line <= 0) return "";
  const std::string& text = doc.analysis->index_text;
  int end_line = loc.end_line > 0 ? loc.end_line : loc.line;
  int end_column = loc.end_line > 0 ? loc.end_column : loc.column + 1;
  size_t begin = offset_of(text, lsp_position(text, loc.line, loc.column));
  size_t end = offset_of(text, lsp_position(text, end_line, end_column));
  return end > begin ? text.substr(begin, end - begin) : "";
}

}  // namespace arbc::lsp
