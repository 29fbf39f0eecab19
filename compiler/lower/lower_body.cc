#include "compiler/lower/lower_body.h"

namespace arbc::lower {

namespace {

using model::BodyExpr;
using model::BodyStmt;

// A constant's folded value as a literal of its type (as codegen writes it into Lua).
BodyExpr constant_literal(const ast::ConstDecl& c) {
  BodyExpr out;
  Type::Kind k = c.value && c.value->type ? c.value->type->kind : Type::Kind::Float;
  switch (k) {
    case Type::Kind::Bool:
      out.op = BodyExpr::Op::Bool;
      out.boolean = c.boolean;
      break;
    case Type::Kind::String:
      out.op = BodyExpr::Op::String;
      out.text = c.text;
      break;
    case Type::Kind::Int:
      out.op = BodyExpr::Op::Int;
      out.number = c.number;
      break;
    default:
      out.op = BodyExpr::Op::Float;
      out.number = c.number;
      break;
  }
  return out;
}

BodyExpr name_expr(const ast::Expr& e) {
  BodyExpr out;
  switch (e.name_kind) {
    case ast::NameKind::Message:
      out.op = BodyExpr::Op::Message;
      break;
    case ast::NameKind::Let:
    case ast::NameKind::Var:
      out.op = BodyExpr::Op::Local;
      out.text = e.local ? e.local->name : e.text;
      break;
    case ast::NameKind::Param:
      out.op = BodyExpr::Op::Param;
      out.text = e.text;
      break;
    case ast::NameKind::Const:
      if (e.constant) return constant_literal(*e.constant);
      break;
    case ast::NameKind::Event:
    case ast::NameKind::Unresolved:
      break;  // not in a checked body
  }
  return out;
}

BodyExpr expr(const ast::Expr& e) {
  using Kind = ast::Expr::Kind;
  BodyExpr out;
  switch (e.kind) {
    case Kind::Number:
      out.op = e.is_int && e.type && e.type->kind == Type::Kind::Int ? BodyExpr::Op::Int
                                                                     : BodyExpr::Op::Float;
      out.number = e.number;
      return out;
    case Kind::Duration:
      out.op = BodyExpr::Op::Float;
      out.number = e.number;
      return out;
    case Kind::String:
      out.op = BodyExpr::Op::String;
      out.text = e.text;
      return out;
    case Kind::Bool:
      out.op = BodyExpr::Op::Bool;
      out.boolean = e.boolean;
      return out;
    case Kind::Name:
      return name_expr(e);
    case Kind::Field:
      out.op = BodyExpr::Op::Field;
      out.text = e.text;
      break;
    case Kind::Index:
      out.op = BodyExpr::Op::Index;
      break;
    case Kind::Unary:
      out.op = e.op == "not" ? BodyExpr::Op::Not : BodyExpr::Op::Neg;
      break;
    case Kind::Binary:
      out.op = BodyExpr::Op::Binary;
      out.text = std::string(e.op);
      break;
    case Kind::Record:
      out.op = BodyExpr::Op::Record;
      for (const auto& field : e.names) out.names.push_back(field.name);
      break;
    case Kind::List:
      out.op = BodyExpr::Op::List;
      break;
    case Kind::Lambda:
      out.op = BodyExpr::Op::Lambda;
      out.text = e.text;
      break;
    case Kind::Call:
      out.op = BodyExpr::Op::Call;
      out.text = e.text;
      break;
    case Kind::Otherwise:
      out.op = BodyExpr::Op::Bool;
      return out;
  }
  for (const ast::ExprPtr& a : e.args) out.args.push_back(expr(*a));
  return out;
}

bool block(const ast::Block& b, std::vector<BodyStmt>& out);

// One statement; false for `script`, whose body is not analysed.
bool stmt(const ast::Stmt& s, std::vector<BodyStmt>& out) {
  using Kind = ast::Stmt::Kind;
  BodyStmt o;
  o.line = s.loc.line;
  o.name = s.name;
  switch (s.kind) {
    case Kind::Let:
      o.kind = BodyStmt::Kind::Let;
      break;
    case Kind::Var:
      o.kind = BodyStmt::Kind::Var;
      break;
    case Kind::Assign:
      o.kind = BodyStmt::Kind::Assign;
      if (s.var_decl) o.name = s.var_decl->name;
      break;
    case Kind::Accept:
      o.kind = BodyStmt::Kind::Accept;
      break;
    case Kind::Set:
      o.kind = BodyStmt::Kind::Set;
      if (s.duration) o.lifetime = s.duration->seconds;
      break;
    case Kind::Unset:
      o.kind = BodyStmt::Kind::Unset;
      break;
    case Kind::If:
      o.kind = BodyStmt::Kind::If;
      if (!block(s.body, o.then_body) || !block(s.else_body, o.else_body)) return false;
      break;
    case Kind::Emit:
      o.kind = BodyStmt::Kind::Emit;
      break;
    case Kind::Throttle:
      o.kind = BodyStmt::Kind::Throttle;
      break;
    case Kind::Every:
      o.kind = BodyStmt::Kind::Every;
      if (!block(s.body, o.then_body)) return false;
      break;
    case Kind::Script:
      return false;
  }
  if (s.expr) o.expr = expr(*s.expr);
  out.push_back(std::move(o));
  return true;
}

bool block(const ast::Block& b, std::vector<BodyStmt>& out) {
  for (const auto& s : b)
    if (!stmt(*s, out)) return false;
  return true;
}

}  // namespace

model::BodyExpr lower_expr(const ast::Expr& e) { return expr(e); }

std::optional<model::Body> lower_body(const ast::Block& body) {
  model::Body out;
  if (!block(body, out)) return std::nullopt;
  return out;
}

model::Assertion lower_assert(const ast::AssertDecl& a) {
  model::Assertion out;
  out.rule = a.rule;
  out.loc = a.loc;
  if (a.over_data) {
    out.property = Constraint::constant(true);
    out.emitted = lower_expr(*a.property);
  } else {
    out.property = a.constraint;
  }
  return out;
}

}  // namespace arbc::lower
