// Text -> AST: UTF-8 validation, lexing, token checks, parsing, AST building.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/frontend/ast.h"
#include "core/diagnostic.h"

namespace arbc::frontend {

// Below this size a second thread costs more than it saves (docs/benchmarks.md).
inline constexpr size_t kTwoThreadParseBytes = 256u << 10;

struct ParseResult {
  std::unique_ptr<ast::Spec> spec;  // null when the text has lexical or syntax errors;
                                    // set (with diagnostics) after AST-level problems
  std::vector<Diagnostic> diagnostics;
};

// Parses one spec. Never throws on bad input: invalid UTF-8, stray characters, syntax errors
// (one per declaration, in the user's words) and nesting beyond kMaxNesting are diagnostics.
// `file` names the text in diagnostics. Texts of `two_thread_bytes` or more are parsed in two
// halves on two threads where they can be (parse_halves.h), with the same result.
ParseResult parse_spec(std::string_view text, const std::string& file,
                       size_t two_thread_bytes = kTwoThreadParseBytes);

}  // namespace arbc::frontend
