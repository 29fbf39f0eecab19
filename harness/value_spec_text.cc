#include "harness/value_spec_text.h"

#include "core/json_text.h"

namespace arbc::harness {

namespace {

// The shortest text that reads back as d, "1.0" for integral ones; nan, inf, -inf.
std::string number(double d) { return float_spec_text(d); }

const Type* element_of(const Type* t) { return t && t->element ? t->element.get() : nullptr; }

const Type* field_type(const Type* t, const std::string& name) {
  const Field* f = t ? t->field(name) : nullptr;
  return f ? f->type.get() : nullptr;
}

}  // namespace

std::string value_spec_text(const Value& v, const Type* type) {
  switch (v.kind()) {
    case Value::Kind::None:
      return "(no value)";
    case Value::Kind::Bool:
      return v.as_bool() ? "true" : "false";
    case Value::Kind::Int:
      return std::to_string(v.as_int());
    case Value::Kind::Float:
      return number(v.as_float());
    case Value::Kind::String: {
      std::string out;
      append_json_string(out, v.as_string());  // the spec's escapes are JSON's
      return out;
    }
    case Value::Kind::Vec3: {
      const Eigen::Vector3d& p = v.as_vec3();
      return "vec3(" + number(p.x()) + ", " + number(p.y()) + ", " + number(p.z()) + ")";
    }
    case Value::Kind::List: {
      std::string out = "[";
      for (size_t i = 0; i < v.size(); ++i)
        out += (i ? ", " : "") + value_spec_text(v[i], element_of(type));
      return out + "]";
    }
    case Value::Kind::Record: {
      std::string out;
      auto field = [&](const std::string& name, const Value& f) {
        out +=
            (out.empty() ? "{ " : ", ") + name + ": " + value_spec_text(f, field_type(type, name));
      };
      if (type && type->kind == Type::Kind::Record) {
        for (const Field& f : type->fields) {
          if (v.has(f.name)) field(f.name, v[f.name]);
        }
        for (const auto& [name, f] : v.as_record()) {  // a field the type lacks, if any
          if (!field_type(type, name)) field(name, f);
        }
      } else {
        for (const auto& [name, f] : v.as_record()) field(name, f);
      }
      return out.empty() ? "{}" : out + " }";
    }
  }
  return "";
}

}  // namespace arbc::harness
