// Constants and constant expressions (docs/language.md#numbers): `const` declarations and every
// operator whose operands are constants, folded as the monitor's Lua computes them
// (const_fold.h). A constant int that overflows 64 bits, an int literal that does not fit and a
// division by a constant zero are errors at their column.
#include "compiler/frontend/sema_context.h"

namespace arbc::frontend {

using namespace ast;

namespace {

std::optional<ConstValue> declared_value(const ConstDecl& c) {
  if (!c.value || !c.value->type) return std::nullopt;
  ConstValue v;
  v.kind = c.value->type->kind;
  switch (v.kind) {
    case Type::Kind::Int:
      v.integer = c.integer;
      return v;
    case Type::Kind::Float:
      v.number = c.number;
      return v;
    case Type::Kind::String:
      v.text = c.text;
      return v;
    case Type::Kind::Bool:
      v.boolean = c.boolean;
      return v;
    default:
      return std::nullopt;
  }
}

}  // namespace

std::optional<ConstValue> Sema::constant_of(const Expr& e) const {
  ConstValue v;
  switch (e.kind) {
    case Expr::Kind::Number:
      if (e.is_int && e.type && e.type->kind == Type::Kind::Int) {
        v.kind = Type::Kind::Int;
        v.integer = e.integer;
      } else {
        v.number = e.number;
      }
      return v;
    case Expr::Kind::Duration:
      v.number = e.number;
      return v;
    case Expr::Kind::String:
      v.kind = Type::Kind::String;
      v.text = e.text;
      return v;
    case Expr::Kind::Bool:
      v.kind = Type::Kind::Bool;
      v.boolean = e.boolean;
      return v;
    case Expr::Kind::Name:
      if (e.name_kind != NameKind::Const || !e.constant) return std::nullopt;
      return declared_value(*e.constant);
    case Expr::Kind::Unary:
    case Expr::Kind::Binary: {
      auto it = folded_.find(&e);
      if (it == folded_.end()) return std::nullopt;
      return it->second;
    }
    default:
      return std::nullopt;
  }
}

void Sema::fold_operator(Expr& e) {
  if (!e.type) return;
  bool binary = e.kind == Expr::Kind::Binary;
  std::optional<ConstValue> a = constant_of(*e.args[0]);
  std::optional<ConstValue> b = binary ? constant_of(*e.args[1]) : std::nullopt;
  std::string why;
  if (binary && (e.op == "/" || e.op == "%") && b && is_zero(*b)) {
    fold_binary(e.op, a ? *a : *b, *b, &why);  // says what dividing by zero gives
    error(e.args[1]->loc, why, diag::DivisionByZero);
    e.type = nullptr;
    return;
  }
  if (!a || (binary && !b)) return;
  std::optional<ConstValue> v =
      binary ? fold_binary(e.op, *a, *b, &why) : fold_unary(e.op, *a, &why);
  if (!v) {
    error(e.loc, why, diag::IntOverflow);
    e.type = nullptr;
    return;
  }
  folded_.emplace(&e, std::move(*v));
}

void Sema::check_const(size_t index) {
  if (const_state_[index] == 2) return;
  ConstDecl& c = spec_.consts[index];
  if (const_state_[index] == 1) {
    error(c.loc,
          "constant '" + c.name +
              "' is defined in terms of itself: compute it from literals and other constants",
          diag::NotConstant);
    const_state_[index] = 2;
    return;
  }
  const_state_[index] = 1;
  Scope empty;
  check_expr(*c.value, empty);
  const_state_[index] = 2;
  if (!c.value->type) return;
  std::optional<ConstValue> v = constant_of(*c.value);
  if (!v) {
    error(c.value->loc,
          "the value of constant '" + c.name +
              "' must be computed from literals and other constants with operators",
          diag::NotConstant);
    c.value->type = nullptr;
    return;
  }
  c.number = v->kind == Type::Kind::Int ? static_cast<double>(v->integer) : v->number;
  c.integer = v->integer;
  c.text = v->text;
  c.boolean = v->boolean;
}

}  // namespace arbc::frontend
