#include "compiler/frontend/literal_value.h"

#include <cmath>

namespace arbc::frontend {

namespace {

using ast::Expr;

std::optional<Value> not_constant(const Expr& e, std::string* err) {
  *err = "not a constant value (write a literal, a constant, a record, a list or vec3(x, y, z))";
  return std::nullopt;
}

// A number as the wanted kind: a float where a float is wanted, else as computed.
Value number(double d, bool is_int, const Type& want) {
  if (want.kind == Type::Kind::Float || !is_int) return Value(d);
  return Value(static_cast<int64_t>(d));
}

std::optional<double> number_of(const Expr& e, std::string* err) {
  Type any_float;
  any_float.kind = Type::Kind::Float;
  std::optional<Value> v = literal_value(e, any_float, err);
  if (!v) return std::nullopt;
  if (!v->is_number()) {
    *err = "not a number";
    return std::nullopt;
  }
  return v->as_float();
}

std::optional<Value> arithmetic(const Expr& e, const Type& want, std::string* err) {
  std::optional<double> a = number_of(*e.args[0], err);
  std::optional<double> b = a ? number_of(*e.args[1], err) : std::nullopt;
  if (!b) return std::nullopt;
  bool ints = e.type && e.type->kind == Type::Kind::Int;
  if (e.op == "+") return number(*a + *b, ints, want);
  if (e.op == "-") return number(*a - *b, ints, want);
  if (e.op == "*") return number(*a * *b, ints, want);
  if (e.op == "/" && *b != 0) return number(*a / *b, false, want);
  if (e.op == "%" && *b != 0) return number(std::fmod(*a, *b), ints, want);
  return not_constant(e, err);
}

std::optional<Value> constant(const Expr& e, const Type& want, std::string* err) {
  const ast::ConstDecl* k = e.constant;
  if (!k || !k->value->type) return not_constant(e, err);
  switch (k->value->type->kind) {
    case Type::Kind::Bool:
      return Value(k->boolean);
    case Type::Kind::String:
      return Value(k->text);
    case Type::Kind::Int:
    case Type::Kind::Float:
      return number(k->number, k->value->type->kind == Type::Kind::Int, want);
    default:
      return not_constant(e, err);
  }
}

std::optional<Value> record(const Expr& e, const Type& want, std::string* err) {
  Value out = Value::record();
  for (size_t i = 0; i < e.args.size(); ++i) {
    const Field* f = want.field(e.names[i].name);
    const Type* field = f ? f->type.get() : nullptr;
    std::optional<Value> v = literal_value(*e.args[i], field ? *field : *e.args[i]->type, err);
    if (!v) return std::nullopt;
    out.set(e.names[i].name, std::move(*v));
  }
  return out;
}

std::optional<Value> list(const Expr& e, const Type& want, std::string* err) {
  Value out = Value::list();
  for (const ast::ExprPtr& item : e.args) {
    const Type* element =
        want.kind == Type::Kind::List && want.element ? want.element.get() : item->type.get();
    std::optional<Value> v = literal_value(*item, *element, err);
    if (!v) return std::nullopt;
    out.push_back(std::move(*v));
  }
  return out;
}

std::optional<Value> vec3(const Expr& e, std::string* err) {
  double xyz[3];
  for (size_t i = 0; i < 3; ++i) {
    std::optional<double> d = number_of(*e.args[i], err);
    if (!d) return std::nullopt;
    xyz[i] = *d;
  }
  return Value::vec3(xyz[0], xyz[1], xyz[2]);
}

std::optional<Value> negate(const Expr& e, const Type& want, std::string* err) {
  std::optional<Value> v = literal_value(*e.args[0], want, err);
  if (!v) return std::nullopt;
  if (v->is_int()) return Value(-v->as_int());
  if (v->is_float()) return Value(-v->as_float());
  if (v->is_vec3()) return Value(Eigen::Vector3d(-v->as_vec3()));
  return not_constant(e, err);
}

}  // namespace

std::optional<Value> literal_value(const Expr& e, const Type& want, std::string* err) {
  if (!e.type) return not_constant(e, err);
  switch (e.kind) {
    case Expr::Kind::Number:
      return number(e.number, e.is_int, want);
    case Expr::Kind::Duration:
      return Value(e.number);
    case Expr::Kind::String:
      return Value(e.text);
    case Expr::Kind::Bool:
      return Value(e.boolean);
    case Expr::Kind::Name:
      if (e.name_kind == ast::NameKind::Const) return constant(e, want, err);
      return not_constant(e, err);
    case Expr::Kind::Record:
      return record(e, want, err);
    case Expr::Kind::List:
      return list(e, want, err);
    case Expr::Kind::Call:
      if (e.builtin == ast::Builtin::Vec3 && e.args.size() == 3) return vec3(e, err);
      return not_constant(e, err);
    case Expr::Kind::Unary:
      if (e.op == "-") return negate(e, want, err);
      if (e.op == "not" && e.args[0]->kind == Expr::Kind::Bool) return Value(!e.args[0]->boolean);
      return not_constant(e, err);
    case Expr::Kind::Binary:
      if (e.type->kind == Type::Kind::Int || e.type->kind == Type::Kind::Float)
        return arithmetic(e, want, err);
      return not_constant(e, err);
    default:
      return not_constant(e, err);
  }
}

}  // namespace arbc::frontend
