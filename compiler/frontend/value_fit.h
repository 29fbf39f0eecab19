// Where a value meets a sized number type (docs/language.md#numbers): a constant goes into any
// number type that holds its value, as C++'s brace initialisation allows (`int8{100}`), and is
// an error at its own column when the type does not hold it (`int8{300}`, a float32 of 0.1, which
// would round). Any other value needs a type that holds every value of its own (assignable()).
#pragma once

#include <optional>
#include <string>

#include "compiler/frontend/ast.h"
#include "core/value.h"

namespace arbc::frontend {

// Whether `value` may go where `want` is expected: assignable(), except that a constant number
// (a literal, a named constant, arithmetic on them) fits every number type of its kind (an int
// constant any number type, a float constant a float type), and record and list literals are
// taken field by field and item by item. Whether the constant is in range is range_miss's
// question.
bool value_fits(const ast::Expr& value, const TypePtr& want);

struct RangeMiss {
  const ast::Expr* at = nullptr;  // the constant
  std::string message;            // "300 does not fit in int8 (-128 to 127)"
};

// The first constant in `value` (itself, or in a field or item of its literals) that is not a
// value of the sized number type it goes into; nullopt when there is none.
std::optional<RangeMiss> range_miss(const ast::Expr& value, const TypePtr& want);

// Why `value` (a list or string) may not have a length `want` allows: a literal's count against
// a fixed or bounded type ("this has 3 elements; float[9] has exactly 9 elements"), or a bounded
// or fixed type whose lengths `want` does not all allow. nullopt when it fits, or is no list or
// string. A hint for check_value_fits's message, whose check is value_fits.
std::optional<std::string> size_miss(const ast::Expr& value, const TypePtr& want);

// The constant value of a number expression, when it is one.
std::optional<Value> constant_number(const ast::Expr& e);

}  // namespace arbc::frontend
