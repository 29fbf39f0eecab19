#include "compiler/frontend/utf8.h"

#include <cstdint>

namespace arbc::frontend {

namespace {

// Length of the valid sequence starting at text[i], or 0 if it is invalid.
size_t sequence_length(std::string_view text, size_t i) {
  auto byte = [&](size_t k) { return static_cast<uint8_t>(text[k]); };
  uint8_t b0 = byte(i);
  if (b0 < 0x80) return 1;
  size_t len;
  uint32_t min_code;
  uint32_t code;
  if ((b0 & 0xE0) == 0xC0) {
    len = 2, min_code = 0x80, code = b0 & 0x1F;
  } else if ((b0 & 0xF0) == 0xE0) {
    len = 3, min_code = 0x800, code = b0 & 0x0F;
  } else if ((b0 & 0xF8) == 0xF0) {
    len = 4, min_code = 0x10000, code = b0 & 0x07;
  } else {
    return 0;
  }
  if (i + len > text.size()) return 0;
  for (size_t k = 1; k < len; ++k) {
    uint8_t b = byte(i + k);
    if ((b & 0xC0) != 0x80) return 0;
    code = (code << 6) | (b & 0x3F);
  }
  if (code < min_code || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return len;
}

}  // namespace

std::optional<Utf8Error> find_invalid_utf8(std::string_view text) {
  Utf8Error where;
  size_t i = 0;
  while (i < text.size()) {
    size_t len = sequence_length(text, i);
    if (len == 0) {
      where.offset = i;
      return where;
    }
    if (text[i] == '\n') {
      ++where.line;
      where.column = 1;
    } else {
      ++where.column;
    }
    i += len;
  }
  return std::nullopt;
}

}  // namespace arbc::frontend
