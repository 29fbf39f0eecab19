// Parsing JSON text with an error a user can act on. nlohmann-json reports a syntax error only
// by throwing, and its text starts with its own tags ("[json.exception.parse_error.101] parse
// error at line 1, column 5: syntax error while parsing value - ..."): caught here, with the
// position as numbers and the tags dropped, so that each reader words the error its own way.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "core/json_place.h"

namespace arbc {

struct JsonParseError {
  // Of the offending character, 1-based, the column in characters (core/text_position.h); 0
  // when there is no place to point at.
  size_t line = 0, column = 0;
  std::string detail;  // "syntax error while parsing value - invalid literal; ..."
};

// From the library's exception: its byte offset (one past the offending byte, 0 for none) in
// text and its what().
JsonParseError json_parse_error(std::string_view text, size_t byte, std::string_view what);

// Parses text into *out (nlohmann::json or ordered_json); false with *error when it is not
// JSON, or holds a number beyond the range of a double.
template <class JsonType>
bool parse_json(std::string_view text, JsonType* out, JsonParseError* error) {
  try {
    *out = JsonType::parse(text.begin(), text.end());
    return true;
  } catch (const typename JsonType::parse_error& e) {
    *error = json_parse_error(text, e.byte, e.what());
  } catch (const typename JsonType::out_of_range& e) {  // a number such as 1e999
    // The library says which literal but not where: found again in the text.
    std::optional<size_t> at = json_number_overflow(text);
    *error = json_parse_error(text, at ? *at + 1 : 0, e.what());
    error->detail += " (beyond the range of a double)";
  }
  return false;
}

}  // namespace arbc
