#include "core/json_diagnostic.h"

namespace arbc {

Diagnostic json_diagnostic(const std::string& file, std::string_view text,
                           const std::vector<std::string>& path, JsonPart part,
                           std::string message) {
  Diagnostic d;
  d.loc.file = file;
  if (std::optional<TextSpan> span = json_place(text, path, part)) {
    d.loc.line = span->begin.line;
    d.loc.column = span->begin.column;
    d.loc.end_line = span->end.line;
    d.loc.end_column = span->end.column;
  }
  d.message = std::move(message);
  return d;
}

Diagnostic json_syntax_diagnostic(const std::string& file, const JsonParseError& e) {
  Diagnostic d;
  d.loc.file = file;
  d.loc.line = static_cast<int>(e.line);
  d.loc.column = static_cast<int>(e.column);
  d.message = json_error_message(e);
  return d;
}

}  // namespace arbc
