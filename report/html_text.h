// Text for HTML and SVG: escaping and the few number formats the run report uses.
#pragma once

#include <string>
#include <string_view>

namespace arbc::report {

// Appends s with the five HTML-special characters (& < > " ') escaped, so any name, message
// or detail is safe both as element text and inside a quoted attribute. NUL and other C0
// control characters except tab, newline and carriage return become U+FFFD: they are not
// allowed in HTML text and would make the SVG invalid XML.
void append_html_escaped(std::string& out, std::string_view s);
std::string html_escape(std::string_view s);

// A time in seconds with 3 decimals ("12.300"): the trace's resolution that matters to a
// reader, and stable across platforms.
std::string seconds_text(double t);

// A short span of time with its unit, to 3 significant digits: "1.67 ms" below a tenth of a
// second (where seconds_text would round 1.67 ms to "0.002"), else "36.000 s".
std::string span_text(double seconds);

// A compact decimal for SVG coordinates: at most 1 decimal, no trailing ".0".
std::string coordinate(double x);

}  // namespace arbc::report
