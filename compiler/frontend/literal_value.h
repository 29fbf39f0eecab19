// The value of a message literal in a test (`at 1s FaceDetector.face <- { pos: vec3(1, 0, 0),
// certainty: 0.9 };`, docs/testing.md): literals, constants, records, lists, vec3(x, y, z),
// unary minus and arithmetic on numbers. Read after sema typed the expression.
#pragma once

#include <optional>
#include <string>

#include "compiler/frontend/ast.h"
#include "core/value.h"

namespace arbc::frontend {

// The value of `e` as a `want` (an int where a float is wanted becomes a float); nullopt with
// *err naming the part that is not a constant value.
std::optional<Value> literal_value(const ast::Expr& e, const Type& want, std::string* err);

}  // namespace arbc::frontend
