#include "compiler/frontend/type_rules.h"

namespace arbc::frontend {

bool assignable(const Type& from, const Type& to) {
  if (from.kind == Type::Kind::Int && to.kind == Type::Kind::Float) return true;
  if (from.kind != to.kind) return false;
  if (from.kind == Type::Kind::List) {
    if (!from.element || !to.element) return true;
    return assignable(*from.element, *to.element);
  }
  if (from.kind != Type::Kind::Record) return true;
  if (from.fields.size() != to.fields.size()) return false;
  for (const Field& f : from.fields) {
    const Field* match = nullptr;
    for (const Field& g : to.fields)
      if (g.name == f.name) match = &g;
    if (!match || !assignable(*f.type, *match->type)) return false;
  }
  return true;
}

bool is_numeric(const TypePtr& t) {
  return t && (t->kind == Type::Kind::Int || t->kind == Type::Kind::Float);
}

bool is_kind(const TypePtr& t, Type::Kind kind) { return t && t->kind == kind; }

std::string type_name(const TypePtr& t) {
  if (!t) return "?";
  switch (t->kind) {
    case Type::Kind::List:
      return "list<" + type_name(t->element) + ">";
    case Type::Kind::Record: {
      std::string s = "{";
      for (size_t i = 0; i < t->fields.size(); ++i) {
        if (i) s += ", ";
        s += t->fields[i].name + ": " + type_name(t->fields[i].type);
      }
      return s + "}";
    }
    default:
      return t->to_string();
  }
}

}  // namespace arbc::frontend
