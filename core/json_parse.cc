#include "core/json_parse.h"

#include "core/text_position.h"

namespace arbc {

JsonParseError json_parse_error(std::string_view text, size_t byte, std::string_view what) {
  JsonParseError error;
  // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ...": the
  // text after the tags, and after the library's own position, which is given as numbers.
  std::string_view detail = what;
  if (size_t tags = detail.find("] "); !detail.empty() && detail[0] == '[' && tags != detail.npos)
    detail = detail.substr(tags + 2);
  size_t position = detail.find("parse error");
  if (position != std::string_view::npos) {
    size_t colon = detail.find(": ", position);
    if (colon != std::string_view::npos) detail = detail.substr(colon + 2);
  }
  error.detail = std::string(detail);
  if (byte == 0) return error;
  TextPosition p = text_position(text, byte - 1);
  error.line = static_cast<size_t>(p.line);
  error.column = static_cast<size_t>(p.column);
  return error;
}

std::string json_error_message(const JsonParseError& e, bool one_line) {
  if (e.first_line == 0) return "not valid JSON: " + e.detail;
  std::string first = one_line ? "column " + std::to_string(e.first_column)
                               : "line " + std::to_string(e.first_line);
  return "key \"" + e.detail + "\" repeated in one object (the first is at " + first +
         "); JSON readers keep only the last value, so remove one of the two";
}

JsonParseError json_repeated_key_error(const JsonRepeatedKey& r) {
  JsonParseError e;
  e.line = static_cast<size_t>(r.second.begin.line);
  e.column = static_cast<size_t>(r.second.begin.column);
  e.first_line = static_cast<size_t>(r.first.begin.line);
  e.first_column = static_cast<size_t>(r.first.begin.column);
  e.detail = r.key;
  return e;
}

}  // namespace arbc
