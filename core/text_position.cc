#include "core/text_position.h"

#include <algorithm>

namespace arbc {

TextPosition text_position(std::string_view text, size_t byte) {
  TextPosition p;
  size_t end = std::min(byte, text.size());
  for (size_t i = 0; i < end; ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      ++p.line;
      p.column = 1;
    } else if ((c & 0xC0) != 0x80) {
      ++p.column;
    }
  }
  return p;
}

}  // namespace arbc
