#include "core/value_json.h"

#include <cmath>
#include <limits>

namespace arbc {

namespace {

const char* json_kind(const nlohmann::json& j) {
  if (j.is_null()) return "null";
  if (j.is_boolean()) return "bool";
  if (j.is_number_integer() || j.is_number_unsigned()) return "int";
  if (j.is_number()) return "float";
  if (j.is_string()) return "string";
  if (j.is_array()) return "list";
  return "record";
}

// "field pos.x: " / "item 3: " / "" at the root: where a mismatch is.
std::string at(const std::string& path) { return path.empty() ? "" : path + ": "; }

std::string child(const std::string& path, const std::string& name) {
  if (path.empty()) return "field " + name;
  return path + "." + name;
}

std::optional<Value> convert(const nlohmann::json& j, const Type& t, const std::string& path,
                             std::string* err);

bool fail(const std::string& path, const std::string& expected, const nlohmann::json& j,
          std::string* err) {
  *err = at(path) + "expected " + expected + ", got " + json_kind(j);
  return false;
}

std::optional<Value> convert_vec3(const nlohmann::json& j, const std::string& path,
                                  std::string* err) {
  double xyz[3];
  static const char* names[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    const nlohmann::json* c = nullptr;
    if (j.is_array() && j.size() == 3) c = &j[i];
    if (j.is_object() && j.size() == 3 && j.contains(names[i])) c = &j[names[i]];
    if (!c) {
      fail(path, "vec3 ({\"x\":..,\"y\":..,\"z\":..} or [x, y, z])", j, err);
      return std::nullopt;
    }
    std::optional<double> d = json_float(*c);
    if (!d) {
      fail(child(path, names[i]), "float", *c, err);
      return std::nullopt;
    }
    xyz[i] = *d;
  }
  return Value::vec3(xyz[0], xyz[1], xyz[2]);
}

// An int is 64 bits: a number outside their range would wrap (2^63 read as -2^63), so it is
// refused, as is a fraction. JSON's parser reads an integer too long for 64 bits as a double,
// which is exact only up to 2^53: a float-form int is taken up to there, and refused beyond
// (-9223372036854775809 reads as exactly -2^63, a silent wrong answer).
std::optional<Value> convert_int(const nlohmann::json& j, const std::string& path,
                                 std::string* err) {
  constexpr double kTwo53 = 9007199254740992.0;
  const char* range =
      "a 64-bit integer, written in digits from -9223372036854775808 to "
      "9223372036854775807";
  if (j.is_number_integer() && !j.is_number_unsigned()) return Value(j.get<int64_t>());
  if (j.is_number_unsigned()) {
    if (j.get<uint64_t>() <= static_cast<uint64_t>(std::numeric_limits<int64_t>::max()))
      return Value(static_cast<int64_t>(j.get<uint64_t>()));
    *err = at(path) + j.dump() + " is beyond the range of int, " + range;
    return std::nullopt;
  }
  if (!j.is_number_float() || std::nearbyint(j.get<double>()) != j.get<double>())
    return fail(path, "int", j, err), std::nullopt;
  double d = j.get<double>();
  if (d >= -kTwo53 && d <= kTwo53) return Value(static_cast<int64_t>(d));
  *err = at(path) + j.dump() + " is not an exact int (a number read as a float beyond 2^53); an " +
         "int is " + range;
  return std::nullopt;
}

std::optional<Value> convert_record(const nlohmann::json& j, const Type& t, const std::string& path,
                                    std::string* err) {
  if (!j.is_object()) {
    fail(path, t.to_string(), j, err);
    return std::nullopt;
  }
  Value out = Value::record();
  for (const Field& f : t.fields) {
    if (!j.contains(f.name)) {
      *err = at(path) + "missing field '" + f.name + "' (" + f.type->to_string() + ")";
      return std::nullopt;
    }
    std::optional<Value> v = convert(j[f.name], *f.type, child(path, f.name), err);
    if (!v) return std::nullopt;
    out.set(f.name, std::move(*v));
  }
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool known = false;
    for (const Field& f : t.fields) known |= f.name == it.key();
    if (!known) {
      *err = at(path) + "unknown field '" + it.key() + "' (the type is " + t.to_string() + ")";
      return std::nullopt;
    }
  }
  return out;
}

std::optional<Value> convert(const nlohmann::json& j, const Type& t, const std::string& path,
                             std::string* err) {
  switch (t.kind) {
    case Type::Kind::Bool:
      if (!j.is_boolean()) return fail(path, "bool", j, err), std::nullopt;
      return Value(j.get<bool>());
    case Type::Kind::Int:
      return convert_int(j, path, err);
    case Type::Kind::Float: {
      std::optional<double> d = json_float(j);
      if (!d) return fail(path, "float", j, err), std::nullopt;
      return Value(*d);
    }
    case Type::Kind::String:
      if (!j.is_string()) return fail(path, t.to_string(), j, err), std::nullopt;
      if (t.size > 0 && j.get_ref<const std::string&>().size() > static_cast<size_t>(t.size)) {
        *err = at(path) + "a string of " + std::to_string(j.get_ref<const std::string&>().size()) +
               " bytes where " + t.to_string() + " holds at most " + std::to_string(t.size);
        return std::nullopt;
      }
      return Value(j.get<std::string>());
    case Type::Kind::Vec3:
      return convert_vec3(j, path, err);
    case Type::Kind::List: {
      if (!j.is_array()) return fail(path, t.to_string(), j, err), std::nullopt;
      if (t.size > 0 && (t.fixed ? j.size() != static_cast<size_t>(t.size)
                                 : j.size() > static_cast<size_t>(t.size))) {
        *err = at(path) + "a list of " + std::to_string(j.size()) + " elements where " +
               t.to_string() + (t.fixed ? " has exactly " : " holds at most ") +
               std::to_string(t.size);
        return std::nullopt;
      }
      Value out = Value::list();
      for (size_t i = 0; i < j.size(); ++i) {
        std::string item = (path.empty() ? "item " : path + " item ") + std::to_string(i);
        std::optional<Value> v = convert(j[i], *t.element, item, err);
        if (!v) return std::nullopt;
        out.push_back(std::move(*v));
      }
      return out;
    }
    case Type::Kind::Record:
      return convert_record(j, t, path, err);
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> json_float(const nlohmann::json& j) {
  if (j.is_number()) return j.get<double>();
  if (!j.is_string()) return std::nullopt;
  const std::string& s = j.get_ref<const std::string&>();
  if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (s == "inf") return std::numeric_limits<double>::infinity();
  if (s == "-inf") return -std::numeric_limits<double>::infinity();
  return std::nullopt;
}

std::optional<Value> value_from_json(const nlohmann::json& j, const Type& t, std::string* err) {
  return convert(j, t, "", err);
}

}  // namespace arbc
