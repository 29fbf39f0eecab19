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

bool needs_escape(unsigned char c, QuoteStyle style) {
  if (c == '"' || c == '\\') return true;
  if (style == QuoteStyle::Dot) return false;
  return c < 0x20 || (style == QuoteStyle::Lua && c >= 0x7f);
}

}  // namespace

// Runs of bytes that stay as they are are copied whole: app.json's source maps and the
// monitors' text make this a large share of writing a big app.
void append_quoted(std::string& out, std::string_view s, QuoteStyle style) {
  out += '"';
  size_t plain = 0;  // where the current run of unescaped bytes starts
  for (size_t i = 0; i < s.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (!needs_escape(c, style)) continue;
    out.append(s, plain, i - plain);
    plain = i + 1;
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else {
      append_numeric_escape(out, c, style);
    }
  }
  out.append(s, plain, s.size() - plain);
  out += '"';
}

std::string quoted(std::string_view s, QuoteStyle style) {
  std::string out;
  append_quoted(out, s, style);
  return out;
}

}  // namespace arbc
