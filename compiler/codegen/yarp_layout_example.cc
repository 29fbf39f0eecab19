#include "compiler/codegen/yarp_layout_example.h"

namespace arbc::codegen {

namespace {

// The elements of a value of type t, as in a message; `nested` wraps a vec3, list or record
// in a sublist, as inside a list or a record.
std::string elements(const Type& t, bool nested) {
  std::string inner;
  switch (t.kind) {
    case Type::Kind::Bool:
      return "1";
    case Type::Kind::Int:
      return "0";
    case Type::Kind::Float:
      return "0.0";
    case Type::Kind::String:
      return "\"text\"";
    case Type::Kind::Vec3:
      inner = "0.0 0.0 0.0";
      break;
    case Type::Kind::List:
      inner = t.element ? elements(*t.element, true) : "";
      break;
    case Type::Kind::Record:
      for (const Field& f : t.fields) {
        if (!inner.empty()) inner += " ";
        inner += "(" + f.name + " " + (f.type ? elements(*f.type, true) : "") + ")";
      }
      break;
  }
  return nested ? "(" + inner + ")" : inner;
}

}  // namespace

std::string yarp_layout_example(const Type& t) { return elements(t, false); }

}  // namespace arbc::codegen
