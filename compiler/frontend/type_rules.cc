#include "compiler/frontend/type_rules.h"

namespace arbc::frontend {

namespace {

// Whether every value of the number type `from` is a value of `to`, so that nothing converts
// it (docs/language.md#numbers); int64 into float64 is the one exception, kept from the
// language before sized types (Lua converts it, rounding beyond 2^53). A uint64 goes nowhere
// else: its bit pattern would read as a negative int64.
bool number_assignable(const Type& from, const Type& to) {
  if (from.kind == Type::Kind::Float) return to.kind == Type::Kind::Float && from.bits <= to.bits;
  if (is_uint64(from)) return is_uint64(to);
  if (to.kind == Type::Kind::Float) return to.bits == 64 || from.bits <= 16;
  if (is_uint64(to)) return from.is_unsigned;
  return from.min_int() >= to.min_int() && from.max_int() <= to.max_int();
}

}  // namespace

bool size_fits(const Type& from, const Type& to) {
  if (to.size == 0) return true;
  if (to.fixed) return from.fixed && from.size == to.size;
  return from.size > 0 && from.size <= to.size;
}

bool assignable(const Type& from, const Type& to, bool sizes) {
  bool from_number = from.kind == Type::Kind::Int || from.kind == Type::Kind::Float;
  bool to_number = to.kind == Type::Kind::Int || to.kind == Type::Kind::Float;
  if (from_number && to_number) return number_assignable(from, to);
  if (from.kind != to.kind) return false;
  if (sizes && !size_fits(from, to)) return false;
  if (from.kind == Type::Kind::List) {
    if (!from.element || !to.element) return true;
    return assignable(*from.element, *to.element, sizes);
  }
  if (from.kind != Type::Kind::Record) return true;
  if (from.fields.size() != to.fields.size()) return false;
  for (const Field& f : from.fields) {
    const Field* match = nullptr;
    for (const Field& g : to.fields)
      if (g.name == f.name) match = &g;
    if (!match || !assignable(*f.type, *match->type, sizes)) return false;
  }
  return true;
}

bool is_numeric(const TypePtr& t) {
  return t && (t->kind == Type::Kind::Int || t->kind == Type::Kind::Float);
}

bool is_kind(const TypePtr& t, Type::Kind kind) { return t && t->kind == kind; }

bool is_stamp(const TypePtr& t) {
  if (!is_kind(t, Type::Kind::Record)) return false;
  for (const char* name : {"sec", "nanosec"}) {
    const Field* f = t->field(name);
    if (!f || !is_kind(f->type, Type::Kind::Int) || is_uint64(*f->type)) return false;
  }
  return true;
}

std::string type_name(const TypePtr& t) {
  if (!t) return "?";
  switch (t->kind) {
    case Type::Kind::List:
      if (t->fixed) return type_name(t->element) + "[" + std::to_string(t->size) + "]";
      if (t->size > 0)
        return "list<" + type_name(t->element) + ", " + std::to_string(t->size) + ">";
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

TypePtr item_join(const TypePtr& a, const TypePtr& b) {
  if (!a || !b) return a ? a : b;  // the empty list literal's element joins with anything
  if (is_numeric(a) && is_numeric(b)) {
    if (is_uint64(*a) != is_uint64(*b)) return nullptr;
    return numeric_join(a, b);
  }
  if (a->kind != b->kind) return nullptr;
  if (a->kind == Type::Kind::List) {
    TypePtr element = item_join(a->element, b->element);
    return element || (!a->element && !b->element) ? Type::list(element) : nullptr;
  }
  if (a->kind == Type::Kind::Record) {
    if (a->fields.size() != b->fields.size()) return nullptr;
    std::vector<Field> fields;
    for (const Field& f : a->fields) {
      const Field* other = b->field(f.name);
      TypePtr joined = other ? item_join(f.type, other->type) : nullptr;
      if (!joined) return nullptr;
      fields.push_back({f.name, joined});
    }
    return Type::record(std::move(fields));
  }
  return assignable(*a, *b) && assignable(*b, *a) ? a : nullptr;
}

}  // namespace arbc::frontend
