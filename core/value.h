// Values carried on ports: bool, int, float, string, vec3 (Eigen), lists and records.
//
// A Value is a small tagged union with value semantics. Lists and records are shared
// copy-on-write, so handing one message to several connections costs a reference count, not a
// deep copy. Record fields are kept sorted by name, which makes JSON output and traces
// deterministic whatever order a producer built them in.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "core/type.h"

namespace arbc {

class Value;
using ValueList = std::vector<Value>;
using ValueRecord = std::map<std::string, Value, std::less<>>;

class Value {
 public:
  // None is "no value": a missing record field, or a default-constructed Value. It is never
  // a valid port value.
  enum class Kind { None, Bool, Int, Float, String, Vec3, List, Record };

  Value() = default;
  Value(bool b) : data_(b) {}
  Value(int i) : data_(int64_t{i}) {}
  Value(int64_t i) : data_(i) {}
  Value(double d) : data_(d) {}
  Value(const char* s) : data_(std::string(s)) {}
  Value(std::string s) : data_(std::move(s)) {}
  Value(std::string_view s) : data_(std::string(s)) {}
  Value(const Eigen::Vector3d& v) : data_(v) {}
  Value(ValueList items);
  Value(ValueRecord fields);

  // Value::list({1, 2, 3}); Value::record({{"verb", "take"}, {"pos", Eigen::Vector3d(1, 2, 3)}})
  static Value list(std::initializer_list<Value> items = {});
  static Value record(std::initializer_list<std::pair<const std::string, Value>> fields = {});
  static Value vec3(double x, double y, double z) { return Value(Eigen::Vector3d(x, y, z)); }

  Kind kind() const { return static_cast<Kind>(data_.index()); }
  bool is_none() const { return kind() == Kind::None; }
  bool is_bool() const { return kind() == Kind::Bool; }
  bool is_int() const { return kind() == Kind::Int; }
  bool is_float() const { return kind() == Kind::Float; }
  bool is_number() const { return is_int() || is_float(); }
  bool is_string() const { return kind() == Kind::String; }
  bool is_vec3() const { return kind() == Kind::Vec3; }
  bool is_list() const { return kind() == Kind::List; }
  bool is_record() const { return kind() == Kind::Record; }

  // Typed access. Each returns a neutral value (false, 0, "", zero vector, empty list/record)
  // when the kind differs, so module code never crashes on a malformed message; check the
  // kind (or rely on the loader's port type checks) when the difference matters.
  bool as_bool() const;
  int64_t as_int() const;   // a float is truncated
  double as_float() const;  // an int is converted
  const std::string& as_string() const;
  const Eigen::Vector3d& as_vec3() const;
  const ValueList& as_list() const;
  const ValueRecord& as_record() const;

  // Mutable access to a list / record (turns a None value into an empty one; detaches a
  // shared payload first).
  ValueList& mutable_list();
  ValueRecord& mutable_record();

  // Record field, or a None value when absent or not a record.
  const Value& operator[](std::string_view field) const;
  // List element, or a None value when out of range or not a list.
  const Value& operator[](size_t index) const;
  bool has(std::string_view field) const;
  size_t size() const;  // list length or record field count; 0 otherwise

  // Builders: v.set("dist", 0.3).set("pos", p); list.push_back(x).
  Value& set(std::string field, Value v);
  Value& push_back(Value v);

  // Compact JSON with fields in name order and doubles printed round-trip exact ("%.17g"
  // shortened): deterministic, used by traces. vec3 prints as {"x":..,"y":..,"z":..}.
  std::string to_json() const;

  friend bool operator==(const Value& a, const Value& b);

 private:
  using Data = std::variant<std::monostate, bool, int64_t, double, std::string, Eigen::Vector3d,
                            std::shared_ptr<ValueList>, std::shared_ptr<ValueRecord>>;
  Data data_;
};

// Does v have type t? Ints conform to float; record fields must match exactly by name.
// On false, *why (when given) says where: "field pos: expected vec3, got string".
bool conforms(const Value& v, const Type& t, std::string* why = nullptr);

}  // namespace arbc
