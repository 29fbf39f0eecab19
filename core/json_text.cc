#include "core/json_text.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/quote.h"

namespace arbc {

// Shortest text that reads back as the same double; integral values keep a ".0" so that
// JSON readers see a float.
void append_json_double(std::string& out, double d) {
  if (!std::isfinite(d)) {
    out += "null";
    return;
  }
  char buf[32];
  for (int precision = 15; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, d);
    if (std::strtod(buf, nullptr) == d) break;
  }
  out += buf;
  if (std::string_view(buf).find_first_of(".eEn") == std::string_view::npos) out += ".0";
}

void append_json_seconds(std::string& out, Nanos t) {
  std::string text = decimal_seconds(t);
  out += text;
  if (text.find('.') == std::string::npos) out += ".0";
}

void append_json_float(std::string& out, double d) {
  if (std::isnan(d)) {
    out += "\"nan\"";
  } else if (std::isinf(d)) {
    out += d > 0 ? "\"inf\"" : "\"-inf\"";
  } else {
    append_json_double(out, d);
  }
}

std::string float_spec_text(double d) {
  if (std::isnan(d)) return "nan";
  if (std::isinf(d)) return d > 0 ? "inf" : "-inf";
  std::string out;
  append_json_double(out, d);
  return out;
}

void append_json_string(std::string& out, std::string_view s) {
  append_quoted(out, s, QuoteStyle::Json);
}

}  // namespace arbc
