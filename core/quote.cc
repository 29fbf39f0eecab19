#include "core/quote.h"

#include <cstdio>

namespace arbc {

namespace {

// The escape of a byte that has no short one (\n...), or nothing when it stays as it is.
bool append_numeric_escape(std::string& out, unsigned char c, QuoteStyle style) {
  char buf[8];
  if (style == QuoteStyle::Json && c < 0x20) {
    std::snprintf(buf, sizeof buf, "\\u%04x", c);
  } else if (style == QuoteStyle::Lua && (c < 0x20 || c >= 0x7f)) {
    std::snprintf(buf, sizeof buf, "\\%03u", static_cast<unsigned>(c));
  } else {
    return false;
  }
  out += buf;
  return true;
}

}  // namespace

void append_quoted(std::string& out, std::string_view s, QuoteStyle style) {
  out += '"';
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (style == QuoteStyle::Dot) {
      out += static_cast<char>(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (!append_numeric_escape(out, c, style)) {
      out += static_cast<char>(c);
    }
  }
  out += '"';
}

std::string quoted(std::string_view s, QuoteStyle style) {
  std::string out;
  append_quoted(out, s, style);
  return out;
}

}  // namespace arbc
