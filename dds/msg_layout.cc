#include "dds/msg_layout.h"

#include <algorithm>

#include "core/join.h"

namespace arbc::dds {

namespace {

using ros2::MsgDefinition;
using ros2::MsgType;

// The spec type a .msg primitive is, with the same bytes on the wire (core/number_types.def
// spells byte and char as uint8; a bounded string is a string, whose bound is not on the wire);
// null for wstring, which a spec cannot declare.
TypePtr spec_type_of(const MsgType& m) {
  if (m.name == "bool") return Type::scalar(Type::Kind::Bool);
  if (m.name == "string") return Type::scalar(Type::Kind::String);
  return Type::number(m.name);
}

std::string bytes_text(int bytes) {
  return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
}

std::string spec_text(const Type& t) {
  switch (t.kind) {
    case Type::Kind::Int:
    case Type::Kind::Float: {
      std::string name = t.to_string();
      std::string full = t.kind == Type::Kind::Float ? "float" : t.is_unsigned ? "uint" : "int";
      full += std::to_string(t.bits);
      return name + " (" + (name == full ? "" : full + ", ") + bytes_text(t.bits / 8) + ")";
    }
    case Type::Kind::Record:
      return "a record";
    default:
      return t.to_string();
  }
}

std::string msg_text(const MsgType& m) {
  TypePtr t = m.primitive && m.array == MsgType::Array::None ? spec_type_of(m) : nullptr;
  if (t && (t->kind == Type::Kind::Int || t->kind == Type::Kind::Float))
    return m.text() + " (" + bytes_text(t->bits / 8) + ")";
  if (t && t->kind == Type::Kind::Bool) return m.text() + " (1 byte)";
  return m.text();
}

// A definition that could not be read, as `file:line:col: what` (the message's name when the
// definition is a built-in one); "" when it was simply not found.
std::string error_text(const ros2::MsgError& e, const std::string& name) {
  if (e.message.empty()) return "";
  return (e.file.empty() ? name
                         : e.file + ":" + std::to_string(e.line) + ":" + std::to_string(e.column)) +
         ": " + e.message;
}

class Comparer {
 public:
  explicit Comparer(ros2::MsgLibrary& library) : library_(library) {}

  // Why `t` at `where` ("" at the top) does not lay out as `m`; "" when it does.
  std::string field(const Type& t, const MsgType& m, const std::string& where) {
    if (m.array != MsgType::Array::None) {
      if (t.kind != Type::Kind::List) return differ(where, spec_text(t), "an array, " + m.text());
      bool fixed = m.array == MsgType::Array::Fixed;
      if (fixed && (!t.fixed || t.size != m.array_size))
        return where + " is " + t.to_string() + " in the spec and " + m.text() +
               " in the message, a fixed array of " + std::to_string(m.array_size) +
               ", which has no length on the wire where a list has one: declare it " +
               t.element->to_string() + "[" + std::to_string(m.array_size) + "]";
      if (!fixed && t.fixed)
        return where + " is " + t.to_string() + " in the spec and " + m.text() +
               " in the message, a sequence, which has its length on the wire where a fixed "
               "array has none: declare it list<" +
               t.element->to_string() + ">";
      MsgType element = m;
      element.array = MsgType::Array::None;
      return field(*t.element, element, where + "[]");
    }
    if (m.primitive) {
      // A bound is not on the wire: string<N> and string lay out alike (the runtime checks N).
      if (m.name == "string" && t.kind == Type::Kind::String) return "";
      TypePtr want = spec_type_of(m);
      if (want && same_type(t, *want)) return "";
      return differ(where, spec_text(t), msg_text(m)) +
             (want ? ": declare it " + want->to_string()
                   : "; a spec cannot declare " + m.name + " (docs/distributed.md#known-limits)");
    }
    const MsgDefinition* def = library_.find(m.name, &error_);
    if (!def) return error_text(error_, m.name);  // not found anywhere: not checked
    if (t.kind == Type::Kind::Vec3) return vec3(*def, where);
    if (t.kind != Type::Kind::Record) return differ(where, spec_text(t), m.text());
    return record(t, *def, where);
  }

  std::string record(const Type& t, const MsgDefinition& def, const std::string& where) {
    std::string at = where.empty() ? "" : where + ".";
    std::vector<std::string> ours, theirs;
    for (const Field& f : t.fields) ours.push_back(f.name);
    for (const ros2::MsgField& f : def.fields) theirs.push_back(f.name);
    std::vector<std::string> a = ours, b = theirs;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (ours != theirs && a == b)
      return "the spec lists " +
             (where.empty() ? "its fields " : "the fields of " + where + " as ") + join(ours) +
             ", but " + def.full_name() + " has them in the order " + join(theirs) +
             "; the bytes come in the message's order and nothing on the wire names a field, so "
             "each would be read as another: list them in the message's order";
    if (ours.size() != theirs.size())
      return (where.empty() ? "the spec's record" : where) + " has " + std::to_string(ours.size()) +
             " fields (" + join(ours) + ") and " + def.full_name() + " has " +
             std::to_string(theirs.size()) + " (" + join(theirs) +
             "): every field of the message is on the wire, in its order";
    for (size_t i = 0; i < ours.size(); ++i) {
      if (!t.fields[i].type) continue;
      std::string inner = field(*t.fields[i].type, def.fields[i].type, at + def.fields[i].name);
      if (!inner.empty()) return inner;
    }
    return "";
  }

 private:
  static std::string differ(const std::string& where, const std::string& ours,
                            const std::string& theirs) {
    return (where.empty() ? "it" : where) + " is " + ours + " in the spec and " + theirs +
           " in the message";
  }

  std::string vec3(const MsgDefinition& def, const std::string& where) {
    bool ok = def.fields.size() == 3;
    for (size_t i = 0; ok && i < 3; ++i)
      ok = def.fields[i].name == std::string(1, "xyz"[i]) && def.fields[i].type.primitive &&
           def.fields[i].type.name == "float64" && def.fields[i].type.array == MsgType::Array::None;
    return ok ? ""
              : (where.empty() ? "it" : where) + " is a vec3 in the spec (float64 x, y, z) and " +
                    def.full_name() + " in the message, which is not three float64 x, y, z";
  }

  ros2::MsgLibrary& library_;
  ros2::MsgError error_;
};

}  // namespace

std::string layout_problem(const std::string& name, const Type& spec, const std::string& message,
                           ros2::MsgLibrary& library) {
  ros2::MsgError error;
  const MsgDefinition* def = library.find(message, &error);
  std::string why;
  if (!def) {
    why = error_text(error, message);
  } else if (spec.kind == Type::Kind::Vec3 || spec.kind == Type::Kind::Record) {
    ros2::MsgType whole;
    whole.primitive = false;
    whole.name = def->full_name();
    why = Comparer(library).field(spec, whole, "");
  } else {
    return "";
  }
  if (why.empty()) return "";
  return "the spec's " + name + " does not lay out as " + (def ? def->full_name() : message) +
         (def && !def->file.empty() ? " (" + def->file + ")" : "") + ": " + why;
}

}  // namespace arbc::dds
