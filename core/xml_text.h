// Text inside XML (and HTML) markup: the one escaping routine for the JUnit report, the YARP
// application file and, through report/html_text.h, the run report's HTML and SVG.
#pragma once

#include <string>
#include <string_view>

namespace arbc {

// Appends `s` safe as element text or inside a double-quoted attribute: & < > " as entities.
// C0 control characters other than tab, newline and carriage return become U+FFFD: XML 1.0
// allows no others, and a report a parser rejects is worse than one odd character.
void append_xml_escaped(std::string& out, std::string_view s);
std::string xml_escaped(std::string_view s);

// `s` safe inside an XML comment `<!-- s -->` (the caller adds the spaces around it): XML
// forbids "--" there and a "-" just before "-->", so each "--" becomes "- -" and a final "-"
// gets a space; the control characters XML forbids become U+FFFD as above. Nothing is escaped
// with entities: a comment has none.
std::string xml_comment_text(std::string_view s);

}  // namespace arbc
