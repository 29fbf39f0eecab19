// The ANTLR parse tree -> AST (ast.h). Decodes literals (numbers, durations, string escapes),
// turns else-if chains into nested If statements, and bounds the depth of operator chains
// (kMaxNesting) so that no later recursive pass can exhaust the stack.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/frontend/ast.h"
#include "core/diagnostic.h"

namespace arbc_grammar {
class ArbcParser;
}

namespace arbc::frontend {

class Builder;

// Builds the AST one top-level declaration at a time, so the caller can free each
// declaration's parse tree before parsing the next. Problems the grammar lets through (bad
// string escapes, chains nested too deeply, malformed types) are appended to `out`; the AST
// is still complete, with placeholders where those were.
class AstBuilder {
 public:
  // `source` is the text the parser read; it must outlive the builder.
  AstBuilder(const std::string& file, std::string_view source, std::vector<Diagnostic>& out);
  ~AstBuilder();
  // `decl` is an ArbcParser::DeclContext* without syntax errors.
  void add_declaration(void* decl);
  // The spec built so far; the builder is spent afterwards.
  std::unique_ptr<ast::Spec> finish();

 private:
  std::unique_ptr<Builder> builder_;
  std::unique_ptr<ast::Spec> spec_;
};

}  // namespace arbc::frontend
