#include "lsp/positions.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace arbc::lsp {

namespace {

// Length in bytes of the UTF-8 sequence starting with `b` (1 for invalid lead bytes).
size_t sequence_length(unsigned char b) {
  return b < 0xC0 ? 1 : b < 0xE0 ? 2 : b < 0xF0 ? 3 : b < 0xF8 ? 4 : 1;
}

size_t line_end(std::string_view text, size_t start) {
  size_t end = text.find('\n', start);
  return end == std::string_view::npos ? text.size() : end;
}

}  // namespace

size_t line_start(std::string_view text, int line) {
  size_t offset = 0;
  for (int l = 0; l < line; ++l) {
    size_t nl = text.find('\n', offset);
    if (nl == std::string_view::npos) return text.size();
    offset = nl + 1;
  }
  return offset;
}

size_t offset_of(std::string_view text, Position p) {
  size_t i = line_start(text, p.line);
  size_t end = line_end(text, i);
  int units = 0;
  while (i < end && units < p.character) {
    size_t len = std::min(sequence_length(static_cast<unsigned char>(text[i])), end - i);
    units += len == 4 ? 2 : 1;
    i += len;
  }
  return i;
}

Position lsp_position(std::string_view text, int line, int column) {
  Position p{std::max(line - 1, 0), 0};
  size_t i = line_start(text, p.line);
  size_t end = line_end(text, i);
  for (int c = 1; c < column && i < end; ++c) {
    size_t len = std::min(sequence_length(static_cast<unsigned char>(text[i])), end - i);
    p.character += len == 4 ? 2 : 1;
    i += len;
  }
  return p;
}

std::pair<int, int> arbc_position(std::string_view text, Position p) {
  size_t start = line_start(text, p.line);
  size_t offset = offset_of(text, p);
  int column = 1;
  for (size_t i = start; i < offset;) {
    i += std::min(sequence_length(static_cast<unsigned char>(text[i])), offset - i);
    ++column;
  }
  return {p.line + 1, column};
}

nlohmann::json position_json(Position p) { return {{"line", p.line}, {"character", p.character}}; }

Position parse_position(const nlohmann::json& j) {
  Position p;
  if (!j.is_object()) return p;
  // A number outside [0, INT_MAX - 1] is clamped (past the end of the text is its end; the
  // 1-based line of arbc_position stays an int).
  constexpr int64_t kMax = std::numeric_limits<int>::max() - 1;
  auto read = [&](const char* name) {
    auto it = j.find(name);
    if (it == j.end() || !it->is_number_integer()) return 0;
    if (it->is_number_unsigned())
      return static_cast<int>(std::min<uint64_t>(it->get<uint64_t>(), kMax));
    return static_cast<int>(std::clamp<int64_t>(it->get<int64_t>(), 0, kMax));
  };
  p.line = read("line");
  p.character = read("character");
  return p;
}

nlohmann::json range_json(std::string_view text, const model::SourceLocation& loc) {
  int end_line = loc.end_line > 0 ? loc.end_line : loc.line;
  int end_column = loc.end_line > 0 ? loc.end_column : loc.column + 1;
  return {{"start", position_json(lsp_position(text, loc.line, loc.column))},
          {"end", position_json(lsp_position(text, end_line, end_column))}};
}

bool contains(const model::SourceLocation& loc, int line, int column) {
  if (loc.line <= 0) return false;
  int end_line = loc.end_line > 0 ? loc.end_line : loc.line;
  int end_column = loc.end_line > 0 ? loc.end_column : loc.column + 1;
  if (line < loc.line || line > end_line) return false;
  if (line == loc.line && column < loc.column) return false;
  if (line == end_line && column > end_column) return false;
  return true;
}

}  // namespace arbc::lsp
