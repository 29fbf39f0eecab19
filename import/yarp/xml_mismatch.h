// Where a hand-written XML file closes an element with the wrong tag. tinyxml2 reports a
// mismatched element at the line where the element *opens*, which sends the user to a line
// that is fine; the typo (`</connectoin>`) is further down. This finds it.
#pragma once

#include <optional>
#include <string>

namespace arbc::yarp {

struct XmlMismatch {
  int line = 0;       // the closing tag that does not match, or the open tag never closed
  int column = 0;     // 1-based
  std::string found;  // e.g. "</connectoin>"; empty when the element is never closed
  std::string open;   // the element it should close, e.g. "<connection>"
  int open_line = 0;  // where that element opens
};

// Scans `text` with a tag stack, skipping comments, CDATA, declarations and processing
// instructions, and returns the first closing tag that does not close the innermost open
// element; when the text ends with elements open, the innermost one. nullopt when the tags
// balance (the error is of another kind).
std::optional<XmlMismatch> find_xml_mismatch(const std::string& text);

}  // namespace arbc::yarp
