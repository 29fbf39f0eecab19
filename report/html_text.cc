#include "report/html_text.h"

#include <cmath>
#include <cstdio>

#include "core/xml_text.h"

namespace arbc::report {

void append_html_escaped(std::string& out, std::string_view s) {
  // HTML escapes ' besides XML's specials, so text is safe in a single-quoted attribute too.
  for (size_t quote; (quote = s.find('\'')) != std::string_view::npos; s.remove_prefix(quote + 1)) {
    append_xml_escaped(out, s.substr(0, quote));
    out += "&#39;";
  }
  append_xml_escaped(out, s);
}

std::string html_escape(std::string_view s) {
  std::string out;
  append_html_escaped(out, s);
  return out;
}

std::string seconds_text(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", t);
  return buffer;
}

std::string span_text(double seconds) {
  if (seconds >= 0.1) return seconds_text(seconds) + " s";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g ms", seconds * 1000);
  return buffer;
}

std::string coordinate(double x) {
  double rounded = std::round(x * 10) / 10;
  if (rounded == 0) rounded = 0;  // no "-0"
  char buffer[32];
  if (rounded == std::floor(rounded)) {
    std::snprintf(buffer, sizeof buffer, "%.0f", rounded);
  } else {
    std::snprintf(buffer, sizeof buffer, "%.1f", rounded);
  }
  return buffer;
}

}  // namespace arbc::report
