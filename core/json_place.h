// Where a key or a value of JSON text is. nlohmann-json keeps no positions: a reader that finds
// a value of the wrong kind, or an unknown key, in what the library parsed places its error by
// scanning the text again along the value's path. Errors are rare and files small, so each
// lookup scans afresh; it keeps no index, and walks nesting with a counter, not recursion.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/text_position.h"

namespace arbc {

// From `begin` to `end`, one past the last character (a diagnostic's end column).
struct TextSpan {
  TextPosition begin, end;
};

enum class JsonPart { Key, Value };

// The span of the member or element at `path` (object keys as the library decoded them,
// decimal indices into arrays; {} is the root) in `text`, which the library parsed: its key
// (a member's, quotes included) or its value (a container from its bracket to its closing
// one). A key that occurs twice in one object is placed at its last occurrence, the one the
// library keeps. Nothing when the path is not in the text, or the text is not JSON there.
std::optional<TextSpan> json_place(std::string_view text, const std::vector<std::string>& path,
                                   JsonPart part = JsonPart::Value);

// A key that occurs a second time in one object: the library keeps its last value and drops
// the first without a word, so readers of user files refuse it (core/json_parse.h).
struct JsonRepeatedKey {
  std::string key;  // as the library decodes it
  TextSpan first, second;
};

// The first key of `text` (which the library parsed) that repeats an earlier key of the same
// object, keys compared as the library decodes them ("a" and "\u0061" are one key); nothing
// when every object's keys are distinct.
std::optional<JsonRepeatedKey> json_repeated_key(std::string_view text);

// The byte offset of the first number literal of `text` that a double cannot hold (1e999),
// which the library reports without a position; nothing when there is none.
std::optional<size_t> json_number_overflow(std::string_view text);

}  // namespace arbc
