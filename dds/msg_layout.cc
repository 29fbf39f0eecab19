#include "dds/msg_layout.h"

#include <algorithm>
#include <map>

#include "core/join.h"

namespace arbc::dds {

namespace {

using ros2::MsgDefinition;
using ros2::MsgType;

// A primitive's bytes on the wire (CDR), and the spec type that has the same layout, if any.
struct Primitive {
  int bytes;
  Type::Kind spec;  // Type::Kind::Record: none
};

const std::map<std::string, Primitive>& primitives() {
  static const std::map<std::string, Primitive> table = {
      {"bool", {1, Type::Kind::Bool}},      {"byte", {1, Type::Kind::Record}},
      {"char", {1, Type::Kind::Record}},    {"int8", {1, Type::Kind::Record}},
      {"uint8", {1, Type::Kind::Record}},   {"int16", {2, Type::Kind::Record}},
      {"uint16", {2, Type::Kind::Record}},  {"int32", {4, Type::Kind::Record}},
      {"uint32", {4, Type::Kind::Record}},  {"float32", {4, Type::Kind::Record}},
      {"int64", {8, Type::Kind::Int}},      {"uint64", {8, Type::Kind::Record}},
      {"float64", {8, Type::Kind::Float}},  {"string", {0, Type::Kind::String}},
      {"wstring", {0, Type::Kind::Record}},
  };
  return table;
}

std::string spec_text(const Type& t) {
  switch (t.kind) {
    case Type::Kind::Int:
      return "int (int64, 8 bytes)";
    case Type::Kind::Float:
      return "float (float64, 8 bytes)";
    case Type::Kind::Record:
      return "a record";
    default:
      return t.to_string();
  }
}

std::string msg_text(const MsgType& m) {
  auto p = primitives().find(m.name);
  if (m.primitive && m.array == MsgType::Array::None && p != primitives().end() && p->second.bytes)
    return m.text() + " (" + std::to_string(p->second.bytes) +
           (p->second.bytes == 1 ? " byte)" : " bytes)");
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
      if (m.array == MsgType::Array::Fixed)
        return where + " is a list in the spec and " + m.text() +
               " in the message, a fixed array, which has no length on the wire where a list "
               "has one";
      MsgType element = m;
      element.array = MsgType::Array::None;
      return field(*t.element, element, where + "[]");
    }
    if (m.primitive) {
      auto p = primitives().find(m.name);
      if (p != primitives().end() && p->second.spec == t.kind) return "";
      return differ(where, spec_text(t), msg_text(m)) +
             (p != primitives().end() && p->second.spec == Type::Kind::Record
                  ? "; a spec cannot declare " + m.name + " yet (docs/distributed.md#known-limits)"
                  : "");
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
