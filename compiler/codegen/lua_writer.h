// Builds Lua source line by line with indentation, and records which spec line each generated
// line comes from (the monitor's source map in app.json).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/app_model.h"

namespace arbc::codegen {

class LuaWriter {
 public:
  // Appends one line at the current indentation; `spec_line` > 0 enters it in the source map.
  void line(std::string_view text, int spec_line = 0);
  void blank() { line(""); }
  void indent() { ++depth_; }
  void dedent() { --depth_; }
  // Appends text that already ends in a newline (a prelude, a script) without indenting it.
  void raw(std::string_view text);

  // Appends everything `other` wrote, shifting its source map to the lines it lands on.
  void append(const LuaWriter& other);

  const std::string& text() const { return text_; }
  int lines() const { return lines_; }
  const std::vector<model::SourceMapEntry>& source_map() const { return map_; }

 private:
  std::string text_;
  std::vector<model::SourceMapEntry> map_;
  int lines_ = 0;
  int depth_ = 0;
};

}  // namespace arbc::codegen
