// Data types of ports and values: bool, the number types of core/number_types.def (int8 to
// uint64, float32, float64; `int` and `float` are int64 and float64), string, vec3, lists and
// records. A list is unbounded (`list<T>`), bounded (`list<T, N>`: at most N elements, ROS 2's
// `T[<=N]`) or fixed (`T[N]`: exactly N, ROS 2's `T[N]`); a string may be bounded (`string<N>`:
// at most N bytes). The bound is part of the type: the proof assumes it, so every value the
// runtime takes in is checked against it (conforms()). Shared by the compiler (type checking),
// app.json and the runtime (port type matching).
//
// Every integer type is held as a 64-bit integer (a Lua 5.4 integer, an int64_t Value) whose
// value is in the type's range; a uint64 is held as its bit pattern, so one above 2^63 - 1 reads
// as a negative int64 to anything that does not know its type (docs/language.md#numbers). A
// float32 is held as the double of the same value.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace arbc {

struct Type;
using TypePtr = std::shared_ptr<const Type>;

struct Field {
  std::string name;
  TypePtr type;
};

struct Type {
  enum class Kind { Bool, Int, Float, String, Vec3, List, Record };
  Kind kind = Kind::Bool;
  int bits = 64;              // Kind::Int: 8, 16, 32 or 64; Kind::Float: 32 or 64
  bool is_unsigned = false;   // Kind::Int
  TypePtr element;            // Kind::List
  int size = 0;               // Kind::List, Kind::String: the bound N; 0: unbounded
  bool fixed = false;         // Kind::List: exactly `size` elements (T[N]), not at most
  std::vector<Field> fields;  // Kind::Record, in declaration order

  static TypePtr scalar(Kind kind);
  static TypePtr list(TypePtr element);
  // list<element, bound> (fixed: element[bound]); string<bound>.
  static TypePtr sized_list(TypePtr element, int bound, bool fixed);
  static TypePtr bounded_string(int bound);
  static TypePtr record(std::vector<Field> fields);
  // The number type a spec spells `name` ("int32", "byte", "float"); null for any other word.
  static TypePtr number(std::string_view name);
  // Every spelling of a number type, in core/number_types.def's order.
  static const std::vector<std::string>& number_names();

  // A number type other than int64 and float64: its values are a subset of theirs.
  bool narrow() const;
  // Kind::Int other than uint64: the least and greatest value.
  int64_t min_int() const;
  int64_t max_int() const;
  // Whether the integer (as a spec writes it, so never above 2^63 - 1) is a value of this
  // integer type; whether the double is a value of this float type (float32: exactly, NaN and
  // the infinities included).
  bool holds(int64_t v) const;
  bool holds(double v) const;
  // "-128 to 127", "0 to 18446744073709551615": an integer type's range, for messages.
  std::string range_text() const;

  // The largest N of T[N], list<T, N> and string<N>: a counterexample holds every element of a
  // fixed list, and its messages stay of a size a test can read.
  static constexpr int kMaxSize = 4096;

  // Canonical text: "list<{pos: vec3, dist: float}>", "float[9]", "list<int, 8>", "string<16>".
  // Fields keep declaration order.
  std::string to_string() const;
  // The record field called `name`; null when there is none (or this is not a record).
  const Field* field(std::string_view name) const;
  // Whether a list is anywhere in it (itself, an element, a field's type).
  bool has_list() const;
};

// The type arithmetic computes in (docs/language.md#numbers): a sized integer promotes to int64
// and float32 to float64 (C's FLT_EVAL_METHOD 1; the value is exact either way), except uint64,
// which stays uint64. `promoted` of a non-number is itself.
TypePtr promoted(const TypePtr& t);
// The type of `a op b` for + - * % and min/max of two numbers: float if either is, else uint64 if
// either is (the checker allows only unsigned partners), else int64.
TypePtr arithmetic_type(const Type& a, const Type& b);
// A uint64: the one number type whose values an int64 does not hold.
bool is_uint64(const Type& t);

// Structural equality; record fields compare by name, in any order.
bool same_type(const Type& a, const Type& b);

// Parses the canonical text form (whitespace-insensitive). Returns nullopt and sets
// *error on malformed text.
TypePtr parse_type(std::string_view text, std::string* error = nullptr);

}  // namespace arbc
