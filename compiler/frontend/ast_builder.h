// The ANTLR parse tree -> AST (ast.h). Decodes literals (numbers, durations, string escapes),
// turns else-if chains into nested If statements, and bounds the depth of operator chains
// (kMaxNesting) so that no later recursive pass can exhaust the stack.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "compiler/diagnostic.h"
#include "compiler/frontend/ast.h"

namespace arbc_grammar {
class ArbcParser;
}

namespace arbc::frontend {

// Builds the AST of a parse tree that has no syntax errors. Problems the grammar lets through
// (bad string escapes, chains nested too deeply, malformed types) are appended to `out`; the
// AST is still complete, with placeholders where those were.
// `tree` is an ArbcParser::SpecContext*.
std::unique_ptr<ast::Spec> build_ast(void* tree, const std::string& file,
                                     std::vector<Diagnostic>& out);

}  // namespace arbc::frontend
