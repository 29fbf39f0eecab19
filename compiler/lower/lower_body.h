// A checked monitor body as the core model's Body (core/body.h): names resolved, constants
// folded into literals, durations in seconds, so the verifier needs no AST
// (docs/design.md#the-proof).
#pragma once

#include <optional>

#include "compiler/frontend/ast.h"
#include "core/body.h"

namespace arbc::lower {

// The body of a rule or connect; nullopt for a `script` body (its Lua is not analysed).
std::optional<model::Body> lower_body(const ast::Block& body);

// A checked expression (a resource's `when`: its message is the delivered value).
model::BodyExpr lower_expr(const ast::Expr& e);

}  // namespace arbc::lower
