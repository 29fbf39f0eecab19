// The parse proper: declaration after declaration from a token stream into the AST builder.
#pragma once

#include <antlr4-runtime.h>

#include "compiler/frontend/ast_builder.h"

namespace arbc::frontend {

// Parses the declarations of `stream` up to its EOF into `builder`, on the calling thread (the
// parser predicts over the thread's own DFA cache). False at the first declaration that does
// not parse: the caller then reports syntax errors (syntax_errors.h).
bool parse_declarations(antlr4::CommonTokenStream& stream, AstBuilder& builder);

}  // namespace arbc::frontend
