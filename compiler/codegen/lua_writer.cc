#include "compiler/codegen/lua_writer.h"

namespace arbc::codegen {

void LuaWriter::line(std::string_view text, int spec_line) {
  ++lines_;
  if (!text.empty()) text_.append(static_cast<size_t>(depth_) * 2, ' ');
  text_ += text;
  text_ += '\n';
  if (spec_line > 0) map_.push_back({lines_, spec_line});
}

void LuaWriter::append(const LuaWriter& other) {
  for (const model::SourceMapEntry& e : other.map_)
    map_.push_back({e.monitor_line + lines_, e.spec_line});
  text_ += other.text_;
  lines_ += other.lines_;
}

void LuaWriter::raw(std::string_view text) {
  text_ += text;
  for (char c : text)
    if (c == '\n') ++lines_;
}

}  // namespace arbc::codegen
