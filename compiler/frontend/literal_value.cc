#include "compiler/frontend/literal_value.h"

#include <cmath>
#include <limits>

#include "compiler/frontend/const_fold.h"

namespace arbc::frontend {

namespace {

using ast::Expr;

std::optional<Value> not_constant(const Expr& e, std::string* err) {
  *err = "not a constant value (write a literal, a constant, a record, a list or vec3(x, y, z))";
  return std::nullopt;
}

// A number as the wanted kind: a float where a float is wanted (an int converted as Lua
// converts it), else as computed.
Value number(const ConstValue& v, const Type& want) {
  if (v.kind == Type::Kind::Int)
    return want.kind == Type::Kind::Float ? Value(static_cast<double>(v.integer))
                                          : Value(v.integer);
  return Value(v.number);
}

std::optional<ConstValue> number_of(const Expr& e, std::string* err) {
  Type any;
  any.kind = e.type && e.type->kind == Type::Kind::Int ? Type::Kind::Int : Type::Kind::Float;
  std::optional<Value> v = literal_value(e, any, err);
  if (!v) return std::nullopt;
  if (!v->is_number()) {
    *err = "not a number";
    return std::nullopt;
  }
  ConstValue c;
  c.kind = v->is_int() ? Type::Kind::Int : Type::Kind::Float;
  c.integer = v->is_int() ? v->as_int() : 0;
  c.number = v->as_float();
  return c;
}

// Arithmetic as the monitor's Lua computes it (const_fold.h): an overflow or a division by
// zero is an error, as in any constant.
std::optional<Value> arithmetic(const Expr& e, const Type& want, std::string* err) {
  std::optional<ConstValue> a = number_of(*e.args[0], err);
  std::optional<ConstValue> b = a ? number_of(*e.args[1], err) : std::nullopt;
  if (!b) return std::nullopt;
  std::optional<ConstValue> r = fold_binary(e.op, *a, *b, err);
  if (!r) return std::nullopt;
  return number(*r, want);
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
    case Type::Kind::Float: {
      ConstValue c;
      c.kind = k->value->type->kind;
      c.integer = k->integer;
      c.number = k->number;
      return number(c, want);
    }
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
    std::optional<ConstValue> d = number_of(*e.args[i], err);
    if (!d) return std::nullopt;
    xyz[i] = d->kind == Type::Kind::Int ? static_cast<double>(d->integer) : d->number;
  }
  return Value::vec3(xyz[0], xyz[1], xyz[2]);
}

std::optional<Value> negate(const Expr& e, const Type& want, std::string* err) {
  std::optional<Value> v = literal_value(*e.args[0], want, err);
  if (!v) return std::nullopt;
  if (v->is_int()) {
    if (v->as_int() == std::numeric_limits<int64_t>::min()) {
      *err = "-(-9223372036854775808) overflows 64 bits";
      return std::nullopt;
    }
    return Value(-v->as_int());
  }
  if (v->is_float()) return Value(-v->as_float());
  if (v->is_vec3()) return Value(Eigen::Vector3d(-v->as_vec3()));
  return not_constant(e, err);
}

}  // namespace

std::optional<Value> literal_value(const Expr& e, const Type& want, std::string* err) {
  if (!e.type) return not_constant(e, err);
  switch (e.kind) {
    case Expr::Kind::Number: {
      ConstValue c;
      c.kind = e.is_int && e.type->kind == Type::Kind::Int ? Type::Kind::Int : Type::Kind::Float;
      c.integer = e.integer;
      c.number = e.number;
      return number(c, want);
    }
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
