// Positions between the LSP's and ours. LSP: 0-based line, column in UTF-16 code units.
// arbc (model::SourceLocation): 1-based line, 1-based column in code points, end exclusive.
// Text is UTF-8; invalid bytes count as one code point each, so nothing here can fail.
#pragma once

#include <nlohmann/json.hpp>
#include <string_view>

#include "core/app_model.h"

namespace arbc::lsp {

struct Position {
  int line = 0;       // 0-based
  int character = 0;  // UTF-16 code units
};

// The byte offset of an LSP position; past the end of a line means its end, past the last
// line the end of the text.
size_t offset_of(std::string_view text, Position p);

// The byte offset where 0-based `line` starts (the text's size past the last line).
size_t line_start(std::string_view text, int line);

// The LSP position of 1-based `line` and code-point `column` of arbc's locations.
Position lsp_position(std::string_view text, int line, int column);

// The arbc (1-based line, code-point column) of an LSP position.
std::pair<int, int> arbc_position(std::string_view text, Position p);

// {"start": ..., "end": ...} for an arbc location (a missing end is the start + 1 column).
nlohmann::json range_json(std::string_view text, const model::SourceLocation& loc);
nlohmann::json position_json(Position p);
Position parse_position(const nlohmann::json& j);  // {"line", "character"}; bad: 0, 0

// Whether (line, column), 1-based code points, lies within loc (end inclusive, so a cursor
// just after a name still names it).
bool contains(const model::SourceLocation& loc, int line, int column);

}  // namespace arbc::lsp
