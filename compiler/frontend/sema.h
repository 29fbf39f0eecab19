// Semantic analysis: resolves every name, types every expression, checks every rule of
// docs/language.md, and fills the AST's "sema:" fields so lowering never resolves again.
#pragma once

#include <vector>

#include "core/diagnostic.h"
#include "compiler/frontend/ast.h"

namespace arbc::frontend {

// Checks a parsed spec in place, appending one diagnostic per problem to `out` (in discovery
// order; the caller sorts). The spec's sema fields are filled wherever names resolved.
void check_spec(ast::Spec& spec, std::vector<Diagnostic>& out);

}  // namespace arbc::frontend
