// UTF-8 validation. The ANTLR 4.9 C++ runtime aborts (std::range_error) on input that is not
// valid UTF-8, so the front end validates every spec before lexing it.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace arbc::frontend {

// Where the first invalid byte is: its byte offset, 1-based line and column (in characters).
struct Utf8Error {
  size_t offset = 0;
  int line = 1;
  int column = 1;
};

// Returns nullopt when `text` is valid UTF-8 (overlong forms, surrogates and code points
// beyond U+10FFFF are invalid); otherwise the position of the first offending byte.
std::optional<Utf8Error> find_invalid_utf8(std::string_view text);

}  // namespace arbc::frontend
