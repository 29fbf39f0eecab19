// Typing rules shared by the checker: when a value of one type may flow where another is
// expected, and how types are printed in messages.
#pragma once

#include <string>

#include "core/type.h"

namespace arbc::frontend {

// True when a value of type `from` may be delivered or stored where `to` is expected:
// the same type (records compare fields by name, in any order), a number type whose values the
// expected one all holds (int8 into int32, uint16 into float32; any int into float64, except
// uint64), element- and field-wise for lists and records. A constant may go into narrower types
// (value_fit.h). An empty list literal (null element)
// fits any list. With `sizes`, a bounded or fixed list or string also needs size_fits();
// without, only the shapes are compared (what `==` between a float[9] and a list<float> needs).
bool assignable(const Type& from, const Type& to, bool sizes = true);
// Whether every length a `from` list or string can have is one `to` allows: anything into an
// unbounded one, T[N] only from T[N], list<T, N> from a bounded or fixed one of at most N.
bool size_fits(const Type& from, const Type& to);

// The scalar types sema gives expressions, one object each for the files that check them.
inline const TypePtr kBool = Type::scalar(Type::Kind::Bool);
inline const TypePtr kInt = Type::scalar(Type::Kind::Int);
inline const TypePtr kFloat = Type::scalar(Type::Kind::Float);
inline const TypePtr kString = Type::scalar(Type::Kind::String);
inline const TypePtr kVec3 = Type::scalar(Type::Kind::Vec3);

// The numeric type of combining a and b: int only if both are, uint64 if either is (core/type.h).
inline TypePtr numeric_join(const TypePtr& a, const TypePtr& b) { return arithmetic_type(*a, *b); }

// The element type of a list literal whose items have types a and b: numbers joined as
// numeric_join joins them, at every depth of records and lists alike (`[{x: 0}, {x: nan}]` is
// a list<{x: float}>, whichever comes first); null when their shapes differ, or a uint64 meets
// another number inside one (a top-level uint64 item: sema_numbers.cc).
TypePtr item_join(const TypePtr& a, const TypePtr& b);

bool is_numeric(const TypePtr& t);
bool is_kind(const TypePtr& t, Type::Kind kind);
// A stamp age() reads: a record with integer fields `sec` and `nanosec` (builtin_interfaces/msg/
// Time, `int32 sec, uint32 nanosec`), neither a uint64 (whose values Lua's integers do not hold).
bool is_stamp(const TypePtr& t);

// "list<{pos: vec3, dist: float}>"; "list<?>" for the empty list literal; "?" for null.
std::string type_name(const TypePtr& t);

}  // namespace arbc::frontend
