// A checked monitor body as the core model's Body (core/body.h), the one translation that the
// verifier encodes and the Lua generators write: names resolved, constants folded into literals
// (which keep the constant's name, for the Lua), durations in seconds, every promotion of an int
// to a float an explicit `ToFloat` node (docs/design.md#numbers-at-run-time), and every node
// typed by core/body_types.h.
#pragma once

#include <optional>

#include "compiler/frontend/ast.h"
#include "core/app_model.h"
#include "core/body.h"

namespace arbc::lower {

// The body of a rule or connect whose message has type `message` and whose deliveries go to a
// port of type `destination` (an `emit` is converted to it); nullopt for a `script` body (its
// Lua is not analysed).
std::optional<model::Body> lower_body(const ast::Block& body, const TypePtr& message,
                                      const TypePtr& destination);

// A checked expression over a message of type `message` (a derived event's predicate, a
// resource's `when` over the delivered value).
model::BodyExpr lower_expr(const ast::Expr& e, const TypePtr& message);

// A checked assertion into a port of type `delivered`: over events (its constraint), or over
// data (its property over `emitted`, the constraint then `true`).
model::Assertion lower_assert(const ast::AssertDecl& a, const TypePtr& delivered);

}  // namespace arbc::lower
