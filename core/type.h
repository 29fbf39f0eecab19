// Data types of ports and values: bool int float string vec3 list<T> and records.
// Shared by the compiler (type checking), app.json and the runtime (port type matching).
#pragma once

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
  TypePtr element;            // Kind::List
  std::vector<Field> fields;  // Kind::Record, in declaration order

  static TypePtr scalar(Kind kind);
  static TypePtr list(TypePtr element);
  static TypePtr record(std::vector<Field> fields);

  // Canonical text: "list<{pos: vec3, dist: float}>". Fields keep declaration order.
  std::string to_string() const;
  // The record field called `name`; null when there is none (or this is not a record).
  const Field* field(std::string_view name) const;
  // Whether a list is anywhere in it (itself, an element, a field's type).
  bool has_list() const;
};

// Structural equality; record fields compare by name, in any order.
bool same_type(const Type& a, const Type& b);

// Parses the canonical text form (whitespace-insensitive). Returns nullopt and sets
// *error on malformed text.
TypePtr parse_type(std::string_view text, std::string* error = nullptr);

}  // namespace arbc
