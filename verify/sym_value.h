// Symbolic values of spec types in Z3 (docs/design.md#the-proof): what the data encoding
// (verify/body_encoding.h) computes for each expression of a body.
//
//   bool -> Bool, int -> a 64-bit bit-vector, float -> IEEE binary64 (verify/lua_number.h: the
//   machine's arithmetic), string -> String (one character per byte), vec3 -> three numbers,
//   record -> its fields (sorted by name, as app values are), list<T> -> a length (an int)
//   and `capacity` element values: elements at or past the length are unused, and so are elements
//   past the capacity of a longer list. A message list has capacity N (the list bound) and any
//   length: a body that reads no element past the capacity is exact for every length; min_by,
//   max_by, min and max also scan its `tail` (stand-ins for the elements past the capacity),
//   which keeps them exact for every length; others assume the length at most N
//   (EncodedBody::bounded).
#pragma once

#include <z3++.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/type.h"
#include "core/value.h"

namespace arbc::verify {

struct SymValue {
  enum class Kind { Bool, Int, Float, String, Vec3, List, Record };
  Kind kind = Kind::Bool;
  z3::expr scalar;                 // Bool/Int/Float/String; List: the length
  std::vector<SymValue> items;     // Vec3: x, y, z; List: elements; Record: fields
  std::vector<std::string> names;  // Record: field names, sorted
  // List (a message's list of any length): stand-ins for its elements past the capacity. Slot j
  // is an element iff the length exceeds items.size() + j; the slots in range are a subsequence
  // of the real elements past the capacity, in order, and the elements after the last slot in
  // range repeat it. A read that scans every element for one (min_by, max_by, min, max) is exact
  // over them as long as no more such reads scan the list than it has slots: each read's choice
  // past the capacity can then be one slot, and a repeated element never changes a choice
  // (docs/design.md#the-proof). Empty: elements past the capacity are not encoded.
  std::vector<SymValue> tail;
  // List: how many leading items are the list's elements at any length (fewer than
  // items.size() only after merging an open list with a longer one, whose extra items the
  // shorter list's padding stands in for).
  size_t exact_items = static_cast<size_t>(-1);

  explicit SymValue(z3::context& ctx) : scalar(ctx.bool_val(true)) {}
  SymValue(Kind k, z3::expr s) : kind(k), scalar(std::move(s)) {}

  bool numeric() const { return kind == Kind::Int || kind == Kind::Float; }
  const SymValue* field(const std::string& name) const;
};

// Fresh constants for a value of type `t` named after `prefix` ("m1.objects"), lists with
// capacity `bound` and `tail_slots` stand-ins past it (SymValue::tail). List lengths get
// 0 <= len, added to `domain`, and len <= bound, added to `within_bound` (assumed only by
// encodings that need it).
SymValue fresh_value(z3::context& ctx, const Type& t, const std::string& prefix, int bound,
                     std::vector<z3::expr>& domain, std::vector<z3::expr>& within_bound,
                     int tail_slots = 0);

// How many of a list's items are its elements whatever its length (SymValue::exact_items).
size_t exact_prefix(const SymValue& list);

// Whether v holds a list whose length is not a constant (its elements past the capacity, if
// any, are not encoded).
bool open_list(const SymValue& v);

// The constant `v` of type `t` (lists get capacity `bound`, unused elements zero).
SymValue constant_value(z3::context& ctx, const Value& v, const Type& t, int bound);

// A fresh value shaped like `v` (a `var`'s unknown state); lists keep v's capacity.
SymValue fresh_like(z3::context& ctx, const SymValue& v, const std::string& prefix);

// The string `s` as a Z3 string of its bytes, one character each, as Lua compares strings.
// Z3_mk_string (z3::context::string_val) reads escapes and mangles bytes outside ASCII: a rule
// accepting only the six bytes `\u{41}` was proved exclusive with one accepting all but "A".
z3::expr byte_string(z3::context& ctx, const std::string& s);

// `if c then a else b`; nullopt when the shapes cannot be merged.
std::optional<SymValue> merge(const z3::expr& c, const SymValue& a, const SymValue& b);

// Structural equality as the generated Lua computes it (`arbc_equal`, numbers by Lua's ==);
// nullopt when the shapes differ.
std::optional<z3::expr> sym_equal(const SymValue& a, const SymValue& b);

// The longest list a witness is built with (concrete; nicer_model tries 256 first): a model
// whose list needs more (`accept len(xs) > 1000000`) is cut there, and its replay on the Lua
// monitors then says that it disagrees, rather than a witness no monitor's memory holds.
inline constexpr int64_t kMaxWitnessElements = int64_t{1} << 12;

// The concrete value of v in a model (list elements up to the length), as an app Value. Elements
// past a list's capacity, which no exact encoding reads, repeat its last encoded element.
Value concrete(const z3::model& m, const SymValue& v);

}  // namespace arbc::verify
