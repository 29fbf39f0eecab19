#include "core/value.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/json_text.h"

namespace arbc {

namespace {

const Value& none_value() {
  static const Value none;
  return none;
}

const std::string& empty_string() {
  static const std::string s;
  return s;
}

void append_json(std::string& out, const Value& v) {
  switch (v.kind()) {
    case Value::Kind::None:
      out += "null";
      break;
    case Value::Kind::Bool:
      out += v.as_bool() ? "true" : "false";
      break;
    case Value::Kind::Int:
      out += std::to_string(v.as_int());
      break;
    case Value::Kind::Float:
      append_json_float(out, v.as_float());
      break;
    case Value::Kind::String:
      append_json_string(out, v.as_string());
      break;
    case Value::Kind::Vec3: {
      const Eigen::Vector3d& p = v.as_vec3();
      out += "{\"x\":";
      append_json_float(out, p.x());
      out += ",\"y\":";
      append_json_float(out, p.y());
      out += ",\"z\":";
      append_json_float(out, p.z());
      out += '}';
      break;
    }
    case Value::Kind::List: {
      out += '[';
      bool first = true;
      for (const Value& e : v.as_list()) {
        if (!first) out += ',';
        first = false;
        append_json(out, e);
      }
      out += ']';
      break;
    }
    case Value::Kind::Record: {
      out += '{';
      bool first = true;
      for (const auto& [name, e] : v.as_record()) {
        if (!first) out += ',';
        first = false;
        append_json_string(out, name);
        out += ':';
        append_json(out, e);
      }
      out += '}';
      break;
    }
  }
}

const char* kind_text(Value::Kind k) {
  switch (k) {
    case Value::Kind::None:
      return "no value";
    case Value::Kind::Bool:
      return "bool";
    case Value::Kind::Int:
      return "int";
    case Value::Kind::Float:
      return "float";
    case Value::Kind::String:
      return "string";
    case Value::Kind::Vec3:
      return "vec3";
    case Value::Kind::List:
      return "list";
    case Value::Kind::Record:
      return "record";
  }
  return "?";
}

}  // namespace

Value::Value(ValueList items) : data_(std::make_shared<ValueList>(std::move(items))) {}
Value::Value(ValueRecord fields) : data_(std::make_shared<ValueRecord>(std::move(fields))) {}

Value Value::list(std::initializer_list<Value> items) { return Value(ValueList(items)); }

Value Value::record(std::initializer_list<std::pair<const std::string, Value>> fields) {
  return Value(ValueRecord(fields.begin(), fields.end()));
}

bool Value::as_bool() const {
  const bool* b = std::get_if<bool>(&data_);
  return b ? *b : false;
}

int64_t Value::as_int() const {
  if (const int64_t* i = std::get_if<int64_t>(&data_)) return *i;
  if (const double* d = std::get_if<double>(&data_)) return static_cast<int64_t>(*d);
  return 0;
}

double Value::as_float() const {
  if (const double* d = std::get_if<double>(&data_)) return *d;
  if (const int64_t* i = std::get_if<int64_t>(&data_)) return static_cast<double>(*i);
  return 0.0;
}

const std::string& Value::as_string() const {
  const std::string* s = std::get_if<std::string>(&data_);
  return s ? *s : empty_string();
}

const Eigen::Vector3d& Value::as_vec3() const {
  static const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const Eigen::Vector3d* v = std::get_if<Eigen::Vector3d>(&data_);
  return v ? *v : zero;
}

const ValueList& Value::as_list() const {
  static const ValueList empty;
  const auto* p = std::get_if<std::shared_ptr<ValueList>>(&data_);
  return p ? **p : empty;
}

const ValueRecord& Value::as_record() const {
  static const ValueRecord empty;
  const auto* p = std::get_if<std::shared_ptr<ValueRecord>>(&data_);
  return p ? **p : empty;
}

ValueList& Value::mutable_list() {
  auto* p = std::get_if<std::shared_ptr<ValueList>>(&data_);
  if (!p) {
    data_ = std::make_shared<ValueList>();
    p = std::get_if<std::shared_ptr<ValueList>>(&data_);
  } else if (p->use_count() > 1) {
    *p = std::make_shared<ValueList>(**p);
  }
  return **p;
}

ValueRecord& Value::mutable_record() {
  auto* p = std::get_if<std::shared_ptr<ValueRecord>>(&data_);
  if (!p) {
    data_ = std::make_shared<ValueRecord>();
    p = std::get_if<std::shared_ptr<ValueRecord>>(&data_);
  } else if (p->use_count() > 1) {
    *p = std::make_shared<ValueRecord>(**p);
  }
  return **p;
}

const Value& Value::operator[](std::string_view field) const {
  const ValueRecord& r = as_record();
  auto it = r.find(field);
  return it == r.end() ? none_value() : it->second;
}

const Value& Value::operator[](size_t index) const {
  const ValueList& l = as_list();
  return index < l.size() ? l[index] : none_value();
}

bool Value::has(std::string_view field) const { return as_record().count(field) > 0; }

size_t Value::size() const {
  if (is_list()) return as_list().size();
  if (is_record()) return as_record().size();
  return 0;
}

Value& Value::set(std::string field, Value v) {
  mutable_record()[std::move(field)] = std::move(v);
  return *this;
}

Value& Value::push_back(Value v) {
  mutable_list().push_back(std::move(v));
  return *this;
}

std::string Value::to_json() const {
  std::string out;
  append_json(out, *this);
  return out;
}

bool operator==(const Value& a, const Value& b) {
  if (a.kind() != b.kind()) return false;
  switch (a.kind()) {
    case Value::Kind::None:
      return true;
    case Value::Kind::Bool:
      return a.as_bool() == b.as_bool();
    case Value::Kind::Int:
      return a.as_int() == b.as_int();
    case Value::Kind::Float:
      return a.as_float() == b.as_float();
    case Value::Kind::String:
      return a.as_string() == b.as_string();
    case Value::Kind::Vec3:
      return a.as_vec3() == b.as_vec3();
    case Value::Kind::List:
      return a.as_list() == b.as_list();
    case Value::Kind::Record:
      return a.as_record() == b.as_record();
  }
  return false;
}

bool conforms(const Value& v, const Type& t, std::string* why) {
  auto fail = [&](std::string text) {
    if (why) *why = std::move(text);
    return false;
  };
  auto mismatch = [&]() {
    return fail("expected " + t.to_string() + ", got " + kind_text(v.kind()));
  };
  switch (t.kind) {
    case Type::Kind::Bool:
      return v.is_bool() || mismatch();
    case Type::Kind::Int:
      if (!v.is_int()) return mismatch();
      // A uint64 is held as its bit pattern (core/type.h): every int64 is one.
      if (t.bits < 64 && !t.holds(v.as_int()))
        return fail(std::to_string(v.as_int()) + " is not " + t.to_string() + " (" +
                    t.range_text() + ")");
      return true;
    case Type::Kind::Float:
      if (!v.is_number()) return mismatch();
      if (!t.holds(v.as_float()))
        return fail(v.to_json() + " is not a " + t.to_string() + " value (it would round)");
      return true;
    case Type::Kind::String:
      if (!v.is_string()) return mismatch();
      if (t.size > 0 && v.as_string().size() > static_cast<size_t>(t.size))
        return fail("a string of " + std::to_string(v.as_string().size()) + " bytes is not a " +
                    t.to_string() + " (at most " + std::to_string(t.size) + " bytes)");
      return true;
    case Type::Kind::Vec3:
      return v.is_vec3() || mismatch();
    case Type::Kind::List: {
      if (!v.is_list()) return mismatch();
      const ValueList& items = v.as_list();
      // T[N] holds exactly N elements, list<T, N> at most N: what the proof assumed of it.
      size_t n = static_cast<size_t>(t.size);
      if (t.size > 0 && (t.fixed ? items.size() != n : items.size() > n))
        return fail("a list of " + std::to_string(items.size()) + " elements is not a " +
                    t.to_string() + (t.fixed ? " (exactly " : " (at most ") +
                    std::to_string(t.size) + ")");
      for (size_t i = 0; i < items.size(); ++i) {
        std::string inner;
        if (!conforms(items[i], *t.element, why ? &inner : nullptr)) {
          return fail("element " + std::to_string(i) + ": " + inner);
        }
      }
      return true;
    }
    case Type::Kind::Record: {
      if (!v.is_record()) return mismatch();
      const ValueRecord& r = v.as_record();
      for (const Field& f : t.fields) {
        auto it = r.find(f.name);
        if (it == r.end()) return fail("missing field " + f.name);
        std::string inner;
        if (!conforms(it->second, *f.type, why ? &inner : nullptr)) {
          return fail("field " + f.name + ": " + inner);
        }
      }
      if (r.size() != t.fields.size()) {
        for (const auto& [name, _] : r) {
          bool known = false;
          for (const Field& f : t.fields) known |= f.name == name;
          if (!known) return fail("unexpected field " + name);
        }
      }
      return true;
    }
  }
  return mismatch();
}

}  // namespace arbc
