// A record literal that names a field its expected type lacks: `emit { verb: "take", poss: p };`
// into a port of `{ verb: string, pos: vec3 }`. A type error over the whole value would hide
// which name is wrong, so the checker reports it at that name, with "did you mean" as for a
// misspelt field read (`o.dsit`).
//
// A literal bound first is traced through its name: in `let c = { poss: p }; emit c;` the
// error is at `poss` in the `let`. That is sound because a `let` is never assigned, so its
// value is its literal, and a `var`'s type is its initializer's, so a stray name there is what
// put the field into the type (an assignment must fit that type). Nothing else is traced: the
// message's type is its port's, a constant is never a record, and a call's or a field's value
// has no literal to point at; those errors stay over the whole value.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compiler/frontend/ast.h"

namespace arbc::frontend {

struct StrayField {
  const ast::Expr::NameAt* name = nullptr;  // the field as written
  TypePtr record;                           // the expected record type, which lacks it
  // The fields of `record` that the literal does not give: what the name may have meant (a
  // field the literal gives already is not).
  std::vector<std::string> missing;
  // The name the literal was reached through (`c` in `emit c;`), the outermost when a `let`
  // names another; null when the literal is written in the value itself.
  const ast::Expr* via = nullptr;
};

// The first field, in source order, of a record literal in `value` (the value itself, one
// nested in the literal's fields or in a list literal's items, or one a `let` or `var` named
// there was bound to) that the type `want` expects there does not have; nullopt when every
// literal's names are the expected ones.
std::optional<StrayField> stray_field(const ast::Expr& value, const TypePtr& want);

}  // namespace arbc::frontend
