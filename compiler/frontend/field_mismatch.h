// A record literal of the right fields whose one field has the wrong type, or that leaves a
// field out: `{ lin: "fast", ang: 0.0 }` where `{ lin: float, ang: float }` is expected. "The
// value is {lin: string, ang: float}, but Base.vel carries Twist" makes the reader compare the
// two types field by field; the checker names the field and points at its value instead.
#pragma once

#include <optional>
#include <string>

#include "compiler/frontend/ast.h"

namespace arbc::frontend {

struct FieldMismatch {
  std::string field;                   // the field's name
  const ast::Expr* value = nullptr;    // its value as written; null when the literal lacks it
  const ast::Expr* literal = nullptr;  // the record literal the field is (or should be) in
  TypePtr want;                        // the type the field should have
};

// The first field, in source order, of a record literal in `value` (itself, or nested in a
// literal's fields or a list literal's items) whose checked type does not fit the type `want`
// expects there, else the first field `want` has that such a literal leaves out; nullopt when
// neither (the mismatch is elsewhere, or the value is not a literal).
std::optional<FieldMismatch> field_mismatch(const ast::Expr& value, const TypePtr& want);

}  // namespace arbc::frontend
