// Constant expressions folded as the generated Lua computes them (docs/language.md#numbers):
// `int` is 64-bit, `float` an IEEE double, an int meets a float as in Lua 5.4 (arithmetic in
// floats, comparisons exact). What a monitor would do silently at run time, wrapping or
// dividing by zero, is an error in a constant: `const K = 9223372036854775807 + 1` is not
// INT64_MIN by intent. The verifier encodes the same arithmetic (verify/lua_number.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/type.h"

namespace arbc::frontend {

struct ConstValue {
  Type::Kind kind = Type::Kind::Float;  // Bool, Int, Float or String
  int64_t integer = 0;                  // Int
  double number = 0;                    // Float
  std::string text;                     // String
  bool boolean = false;                 // Bool
};

// `a op b` (op one of + - * / % < <= > >= == != and or); nullopt and *error (what is wrong and
// what to write instead) when it overflows 64 bits or divides by zero.
std::optional<ConstValue> fold_binary(std::string_view op, const ConstValue& a, const ConstValue& b,
                                      std::string* error);

// -a and `not a`; nullopt and *error when -a overflows (-(-9223372036854775807 - 1)).
std::optional<ConstValue> fold_unary(std::string_view op, const ConstValue& a, std::string* error);

// Whether a constant divisor is zero (an int 0, or a float +-0.0): `x / 0` and `x % 0` are
// errors whatever x is.
bool is_zero(const ConstValue& v);

}  // namespace arbc::frontend
