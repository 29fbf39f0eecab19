#include "compiler/lower/lower_body.h"

#include "core/body_types.h"

namespace arbc::lower {

namespace {

using model::BodyExpr;
using model::BodyStmt;
using TK = Type::Kind;

bool is(const TypePtr& t, TK k) { return t && t->kind == k; }
bool numeric(const TypePtr& t) { return is(t, TK::Int) || is(t, TK::Float); }

const TypePtr& float_type() {
  static const TypePtr f = Type::scalar(TK::Float);
  return f;
}

BodyExpr to_float(BodyExpr x) {
  BodyExpr c;
  c.op = BodyExpr::Op::ToFloat;
  c.args.push_back(std::move(x));
  return c;
}

// A constant's folded value as a literal of its type, named after the constant.
BodyExpr constant_literal(const ast::ConstDecl& c) {
  BodyExpr out;
  TK k = c.value && c.value->type ? c.value->type->kind : TK::Float;
  switch (k) {
    case TK::Bool:
      out.op = BodyExpr::Op::Bool;
      out.boolean = c.boolean;
      break;
    case TK::String:
      out.op = BodyExpr::Op::String;
      out.text = c.text;
      break;
    case TK::Int:
      out.op = BodyExpr::Op::Int;
      out.integer = c.integer;
      if (is_uint64(*c.value->type)) out.text = model::kUint64Literal;
      break;
    default:
      out.op = BodyExpr::Op::Float;
      out.number = c.number;
      break;
  }
  out.constant = c.name;
  out.constant_line = c.loc.line;
  out.constant_column = c.loc.column;
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

BodyExpr expr(const ast::Expr& e);
BodyExpr coerce(const ast::Expr& e, const TypePtr& want);

// A list literal whose items are wanted as `element` (null: as they are).
BodyExpr list_of(const ast::Expr& e, const TypePtr& element) {
  BodyExpr out;
  out.op = BodyExpr::Op::List;
  for (const ast::ExprPtr& item : e.args) out.args.push_back(coerce(*item, element));
  return out;
}

// e as a value of type `want`: an int where a float is wanted is converted (docs/design.md
// #numbers-at-run-time), and so, item by item, are the ints of a list or record literal whose
// items or fields are wanted as floats. Without `want`, e as it is.
BodyExpr coerce(const ast::Expr& e, const TypePtr& want) {
  if (!want || !e.type) return expr(e);
  if (is(e.type, TK::Int) && is(want, TK::Float)) return to_float(expr(e));
  if (e.kind == ast::Expr::Kind::List && is(want, TK::List) && want->element)
    return list_of(e, want->element);
  if (e.kind == ast::Expr::Kind::Record && is(want, TK::Record)) {
    BodyExpr out;
    out.op = BodyExpr::Op::Record;
    for (size_t i = 0; i < e.args.size(); ++i) {
      const Field* f = want->field(e.names[i].name);
      out.names.push_back(e.names[i].name);
      out.args.push_back(coerce(*e.args[i], f ? f->type : nullptr));
    }
    return out;
  }
  return expr(e);
}

// `a op b`. Arithmetic whose type is float converts its int operands, so does a comparison of
// an int with a float (Lua would compare them exactly, the spec compares them as floats), and a
// vec3 scaled by an int.
BodyExpr binary(const ast::Expr& e) {
  BodyExpr out;
  out.op = BodyExpr::Op::Binary;
  out.text = std::string(e.op);
  const ast::Expr& a = *e.args[0];
  const ast::Expr& b = *e.args[1];
  std::string_view op = e.op;
  bool arith = op == "+" || op == "-" || op == "*" || op == "/" || op == "%";
  bool compare = op == "<" || op == "<=" || op == ">" || op == ">=" || op == "==" || op == "!=";
  TypePtr want;
  if (arith && (is(e.type, TK::Float) || is(e.type, TK::Vec3))) want = float_type();
  if (compare && numeric(a.type) && numeric(b.type) &&
      !(is(a.type, TK::Int) && is(b.type, TK::Int)))
    want = float_type();
  out.args.push_back(coerce(a, want));
  out.args.push_back(coerce(b, want));
  return out;
}

// A builtin call: `min`/`max` of a float type and `vec3` take their int arguments as floats.
BodyExpr call(const ast::Expr& e) {
  BodyExpr out;
  out.op = BodyExpr::Op::Call;
  out.text = e.text;
  out.builtin = e.builtin;
  bool floats = e.builtin == Builtin::Vec3 ||
                ((e.builtin == Builtin::Min || e.builtin == Builtin::Max) && is(e.type, TK::Float));
  for (const ast::ExprPtr& a : e.args)
    out.args.push_back(coerce(*a, floats ? float_type() : nullptr));
  return out;
}

BodyExpr expr(const ast::Expr& e) {
  using Kind = ast::Expr::Kind;
  BodyExpr out;
  switch (e.kind) {
    case Kind::Number:
      out.op = e.is_int && is(e.type, TK::Int) ? BodyExpr::Op::Int : BodyExpr::Op::Float;
      out.number = e.number;
      out.integer = e.integer;
      if (out.op == BodyExpr::Op::Int && is_uint64(*e.type)) out.text = model::kUint64Literal;
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
    case Kind::Binary:
      return binary(e);
    case Kind::Call:
      return call(e);
    case Kind::List:  // one element type: ints among floats become floats
      return list_of(e, is(e.type, TK::List) ? e.type->element : nullptr);
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
    case Kind::Record:
      out.op = BodyExpr::Op::Record;
      for (const auto& field : e.names) out.names.push_back(field.name);
      break;
    case Kind::Lambda:
      out.op = BodyExpr::Op::Lambda;
      out.text = e.text;
      break;
    case Kind::Otherwise:
      out.op = BodyExpr::Op::Bool;
      return out;
  }
  for (const ast::ExprPtr& a : e.args) out.args.push_back(expr(*a));
  return out;
}

bool block(const ast::Block& b, const TypePtr& destination, std::vector<BodyStmt>& out);

// One statement; false for `script`, whose body is not analysed. An `emit` is converted to the
// destination's type, an assignment to the type of its `var`.
bool stmt(const ast::Stmt& s, const TypePtr& destination, std::vector<BodyStmt>& out) {
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
      if (s.duration) o.lifetime = s.duration->nanos;
      break;
    case Kind::Unset:
      o.kind = BodyStmt::Kind::Unset;
      break;
    case Kind::If:
      o.kind = BodyStmt::Kind::If;
      if (!block(s.body, destination, o.then_body) || !block(s.else_body, destination, o.else_body))
        return false;
      break;
    case Kind::Emit:
      o.kind = BodyStmt::Kind::Emit;
      break;
    case Kind::Throttle:
      o.kind = BodyStmt::Kind::Throttle;
      break;
    case Kind::Every:
      o.kind = BodyStmt::Kind::Every;
      if (!block(s.body, destination, o.then_body)) return false;
      break;
    case Kind::Script:
      return false;
  }
  TypePtr want;
  if (s.kind == Kind::Emit) want = destination;
  if (s.kind == Kind::Assign && s.var_decl && s.var_decl->expr) want = s.var_decl->expr->type;
  if (s.expr) o.expr = coerce(*s.expr, want);
  out.push_back(std::move(o));
  return true;
}

bool block(const ast::Block& b, const TypePtr& destination, std::vector<BodyStmt>& out) {
  for (const auto& s : b)
    if (!stmt(*s, destination, out)) return false;
  return true;
}

}  // namespace

model::BodyExpr lower_expr(const ast::Expr& e, const TypePtr& message) {
  BodyExpr out = expr(e);
  model::type_expr(out, message);
  return out;
}

std::optional<model::Body> lower_body(const ast::Block& body, const TypePtr& message,
                                      const TypePtr& destination) {
  model::Body out;
  if (!block(body, destination, out)) return std::nullopt;
  model::type_body(out, message);
  return out;
}

model::Assertion lower_assert(const ast::AssertDecl& a, const TypePtr& delivered) {
  model::Assertion out;
  out.rule = a.rule;
  out.loc = a.loc;
  if (a.over_data) {
    out.property = Constraint::constant(true);
    out.emitted = lower_expr(*a.property, delivered);
  } else {
    out.property = a.constraint;
  }
  return out;
}

}  // namespace arbc::lower
