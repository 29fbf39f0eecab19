// Parsing JSON text with an error a user can act on. nlohmann-json reports a syntax error only
// by throwing, and its text starts with its own tags ("[json.exception.parse_error.101] parse
// error at line 1, column 5: syntax error while parsing value - ..."): caught here, with the
// position as numbers and the tags dropped, so that each reader words the error its own way.
// It also resolves a key repeated in one object to its last value without a word: a file the
// user wrote that repeats a key is refused here, at the second key, for every reader alike.
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
  // For a key repeated in one object (at line and column): where the key first is, and the
  // key in `detail`; 0 for text that is not JSON.
  size_t first_line = 0, first_column = 0;
};

// What is wrong, for after the error's position: "not valid JSON: <detail>", or for a repeated
// key what to do about it and where the first one is. `one_line`: the reader parses each line
// of a file alone (JSON lines), so the first key is named by its column only.
std::string json_error_message(const JsonParseError& e, bool one_line = false);

// The error for a repeated key (core/json_place.h).
JsonParseError json_repeated_key_error(const JsonRepeatedKey& r);

// From the library's exception: its byte offset (one past the offending byte, 0 for none) in
// text and its what().
JsonParseError json_parse_error(std::string_view text, size_t byte, std::string_view what);

// Parses text into *out (nlohmann::json or ordered_json); false with *error when it is not
// JSON, holds a number beyond the range of a double, or repeats a key in one object.
template <class JsonType>
bool parse_json(std::string_view text, JsonType* out, JsonParseError* error) {
  try {
    *out = JsonType::parse(text.begin(), text.end());
    std::optional<JsonRepeatedKey> repeated = json_repeated_key(text);
    if (!repeated) return true;
    *error = json_repeated_key_error(*repeated);
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
