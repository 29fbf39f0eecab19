// Semantic analysis: resolves every name, types every expression, checks every rule of
// docs/language.md, and fills the AST's "sema:" fields so lowering never resolves again.
#pragma once

#include <string>
#include <vector>

#include "compiler/frontend/ast.h"
#include "core/diagnostic.h"

namespace arbc::frontend {

// Checks a parsed spec in place, appending one diagnostic per problem to `out` (in discovery
// order; the caller sorts). The spec's sema fields are filled wherever names resolved.
// `script_dir` is where `script "file.lua"` paths are relative to; empty means the spec file's
// folder (and no script check for a spec that is not a file on disk).
void check_spec(ast::Spec& spec, std::vector<Diagnostic>& out, const std::string& script_dir = "");

// The most rules one `by priority` port may have (sema_priority.cc says why).
inline constexpr size_t kMaxPriorityRules = 1000;

// Rules above the lowest of a `by priority` port whose activity event (act_<rule>) is also a
// declared event, and ports with more than kMaxPriorityRules rules: one "priority" error each
// (sema_priority.cc). Reads sema's event symbols.
void check_activity_names(const ast::Spec& spec, std::vector<Diagnostic>& out);

}  // namespace arbc::frontend
