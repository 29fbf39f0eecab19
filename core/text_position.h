// Where a byte of a text is, as diagnostics give it (core/diagnostic.h): a 1-based line and a
// 1-based column that counts characters, not bytes, so that a caret under a line with "µ" or
// "é" before the place still points at it.
#pragma once

#include <cstddef>
#include <string_view>

namespace arbc {

struct TextPosition {
  int line = 1;
  int column = 1;
};

// The position of the character that starts at `byte` (a byte past the end: the position just
// after the last character). Lines end at '\n'; a UTF-8 continuation byte is no new column.
TextPosition text_position(std::string_view text, size_t byte);

}  // namespace arbc
