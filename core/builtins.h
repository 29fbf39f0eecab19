// The spec language's builtin functions (docs/language.md#builtins), listed once. Clang's
// Builtins.def is the model: one table that every stage reads instead of its own list.
//
//   the checker (compiler/frontend/sema_expr.cc)   which names exist, their arity, the signature
//                                                  its messages quote; "did you mean" candidates
//   the Lua generators (compiler/codegen/)          the prelude helper a call needs (lua_prelude.h)
//   the Z3 encoder (verify/body_encoding.cc)        a switch on the id (-Wswitch names a missing
//   case) the language server (lsp/)                      completion items and hover text
//
// The argument and result types are the checker's (sema_expr.cc check_builtin_args) and the
// IR's typing (core/body_types.cc); the Lua source of each helper is in lua_prelude.cc. Adding
// a builtin: a row here, an id in `Builtin`, then the compiler and the tests say what is missing
// (lua_prelude_test, verify's builtin_encoding_test).
#pragma once

#include <string>
#include <string_view>

namespace arbc {

enum class Builtin : unsigned char {
  None,
  Len,
  MinBy,
  MaxBy,
  Dist,
  Norm,
  Abs,
  Min,
  Max,
  Now,
  Age,
  Vec3
};

struct BuiltinInfo {
  Builtin id;
  std::string_view name;
  int min_args;
  int max_args;                 // -1: any number
  std::string_view signature;   // quoted by arity and type errors, completion and hover
  std::string_view summary;     // one sentence for hover
  std::string_view lua_helper;  // the prelude function generated Lua calls (lua_prelude.h)
};

inline constexpr BuiltinInfo kBuiltins[] = {
    {Builtin::Len, "len", 1, 1, "len(list or string) -> int",
     "The number of elements of a list, or of bytes of a string.", "len"},
    {Builtin::MinBy, "min_by", 2, 2, "min_by(list<T>, x => number) -> T",
     "The first element with the smallest key; no value for an empty list.", "min_by"},
    {Builtin::MaxBy, "max_by", 2, 2, "max_by(list<T>, x => number) -> T",
     "The first element with the largest key; no value for an empty list.", "max_by"},
    {Builtin::Dist, "dist", 2, 2, "dist(vec3, vec3) -> float",
     "The Euclidean distance between two points.", "dist"},
    {Builtin::Norm, "norm", 1, 1, "norm(vec3) -> float", "The length of a vector.", "norm"},
    {Builtin::Abs, "abs", 1, 1, "abs(number) -> number",
     "The absolute value, of the argument's type.", "abs"},
    {Builtin::Min, "min", 2, -1, "min(number, number, ...) -> number",
     "The smallest argument; a float if any argument is one.", "min"},
    {Builtin::Max, "max", 2, -1, "max(number, number, ...) -> number",
     "The largest argument; a float if any argument is one.", "max"},
    {Builtin::Now, "now", 0, 0, "now() -> float (seconds)",
     "The runtime's clock in seconds (simulated time in a simulated run).", "now"},
    {Builtin::Age, "age", 1, 1, "age({sec, nanosec}) -> duration",
     "How long ago a ROS 2 stamp was, on the run's clock read as ROS 2 time (the simulated "
     "clock in simulation).",
     "age"},
    {Builtin::Vec3, "vec3", 3, 3, "vec3(x, y, z) -> vec3", "A vector of three floats.", "vec3"},
};

// The row of `name`; null when it is no builtin.
const BuiltinInfo* find_builtin(std::string_view name);

// The row of `id`; null for Builtin::None.
const BuiltinInfo* builtin_info(Builtin id);

// "len, min_by, max_by, dist, norm, abs, min, max, now, age, vec3": the names in table order.
std::string builtin_names_text();

}  // namespace arbc
