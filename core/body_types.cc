#include "core/body_types.h"

#include <map>

namespace arbc::model {

namespace {

const TypePtr& scalar(Type::Kind k) {
  static const TypePtr kinds[] = {Type::scalar(Type::Kind::Bool), Type::scalar(Type::Kind::Int),
                                  Type::scalar(Type::Kind::Float), Type::scalar(Type::Kind::String),
                                  Type::scalar(Type::Kind::Vec3)};
  return kinds[static_cast<int>(k)];  // Bool, Int, Float, String, Vec3 come first in Type::Kind
}

bool is(const TypePtr& t, Type::Kind k) { return t && t->kind == k; }
bool numeric(const TypePtr& t) { return is(t, Type::Kind::Int) || is(t, Type::Kind::Float); }

// int only if both are, uint64 if either is (core/type.h, as sema's numeric_join).
TypePtr join(const TypePtr& a, const TypePtr& b) { return arithmetic_type(*a, *b); }

class Typer {
 public:
  explicit Typer(TypePtr message) : message_(std::move(message)) {}

  bool ok() const { return ok_; }

  TypePtr expr(BodyExpr& e) {
    e.type = compute(e);
    if (!e.type && e.op != BodyExpr::Op::Lambda) ok_ = false;
    return e.type;
  }

  void block(std::vector<BodyStmt>& b) {
    for (BodyStmt& s : b) stmt(s);
  }

 private:
  TypePtr compute(BodyExpr& e);
  TypePtr field(BodyExpr& e);
  TypePtr binary(BodyExpr& e);
  TypePtr list(BodyExpr& e);
  TypePtr call(BodyExpr& e);
  void stmt(BodyStmt& s);

  // The locals of a nested block end with it.
  void nested(std::vector<BodyStmt>& b) {
    std::map<std::string, TypePtr> outer = locals_;
    block(b);
    locals_ = std::move(outer);
  }

  TypePtr message_;
  std::map<std::string, TypePtr> locals_, params_;
  bool ok_ = true;
};

TypePtr Typer::compute(BodyExpr& e) {
  using Op = BodyExpr::Op;
  switch (e.op) {
    case Op::Message:
      return message_;
    case Op::Int:
      return e.text == kUint64Literal ? Type::number("uint64") : scalar(Type::Kind::Int);
    case Op::Float:
      return scalar(Type::Kind::Float);
    case Op::String:
      return scalar(Type::Kind::String);
    case Op::Bool:
      return scalar(Type::Kind::Bool);
    case Op::Local:
    case Op::Param: {
      const auto& scope = e.op == Op::Local ? locals_ : params_;
      auto it = scope.find(e.text);
      return it != scope.end() ? it->second : nullptr;
    }
    case Op::Field:
      return field(e);
    case Op::Index: {
      TypePtr base = expr(e.args[0]);
      expr(e.args[1]);
      return is(base, Type::Kind::List) ? base->element : nullptr;
    }
    case Op::Neg:
      return promoted(expr(e.args[0]));
    case Op::Not:
      expr(e.args[0]);
      return scalar(Type::Kind::Bool);
    case Op::Binary:
      return binary(e);
    case Op::Record: {
      std::vector<Field> fields;
      bool typed = true;
      for (size_t i = 0; i < e.args.size() && i < e.names.size(); ++i) {
        TypePtr t = expr(e.args[i]);
        typed = typed && t;
        fields.push_back({e.names[i], t});
      }
      return typed ? Type::record(std::move(fields)) : nullptr;
    }
    case Op::List:
      return list(e);
    case Op::Lambda:
      return nullptr;  // typed where min_by / max_by binds its parameter
    case Op::Call:
      return call(e);
    case Op::ToFloat:
      expr(e.args[0]);
      return scalar(Type::Kind::Float);
  }
  return nullptr;
}

TypePtr Typer::field(BodyExpr& e) {
  TypePtr base = expr(e.args[0]);
  if (is(base, Type::Kind::Vec3))
    return e.text == "x" || e.text == "y" || e.text == "z" ? scalar(Type::Kind::Float) : nullptr;
  const Field* f = base ? base->field(e.text) : nullptr;
  return f ? f->type : nullptr;
}

TypePtr Typer::binary(BodyExpr& e) {
  TypePtr a = expr(e.args[0]);
  TypePtr b = expr(e.args[1]);
  const std::string& op = e.text;
  if (op == "and" || op == "or" || op == "==" || op == "!=" || op == "<" || op == "<=" ||
      op == ">" || op == ">=")
    return scalar(Type::Kind::Bool);
  if (numeric(a) && numeric(b)) return op == "/" ? scalar(Type::Kind::Float) : join(a, b);
  if (is(a, Type::Kind::Vec3) || is(b, Type::Kind::Vec3)) return scalar(Type::Kind::Vec3);
  // A concatenation's length is not its operand's: it has no bound.
  if (op == "+" && is(a, Type::Kind::String)) return scalar(Type::Kind::String);
  if (op == "+" && is(a, Type::Kind::List)) return Type::list(a->element);
  return nullptr;
}

// One element type: the first item's, ints and floats together floats (sema's check_list).
TypePtr Typer::list(BodyExpr& e) {
  TypePtr element;
  for (BodyExpr& item : e.args) {
    TypePtr t = expr(item);
    if (!element)
      element = t;
    else if (numeric(element) && numeric(t))
      element = join(element, t);
  }
  return Type::list(element);
}

TypePtr Typer::call(BodyExpr& e) {
  if (e.builtin == Builtin::MinBy || e.builtin == Builtin::MaxBy) {
    TypePtr xs = e.args.empty() ? nullptr : expr(e.args[0]);
    if (e.args.size() != 2 || e.args[1].op != BodyExpr::Op::Lambda || !is(xs, Type::Kind::List))
      return nullptr;
    BodyExpr& lambda = e.args[1];
    std::map<std::string, TypePtr> outer = params_;
    params_[lambda.text] = xs->element;
    expr(lambda.args[0]);
    params_ = std::move(outer);
    return xs->element;
  }
  std::vector<TypePtr> args;
  for (BodyExpr& a : e.args) args.push_back(expr(a));
  switch (e.builtin) {
    case Builtin::Len:
      return scalar(Type::Kind::Int);
    case Builtin::Dist:
    case Builtin::Norm:
    case Builtin::Now:
    case Builtin::Age:
      return scalar(Type::Kind::Float);
    case Builtin::Abs:
      return args.size() == 1 ? promoted(args[0]) : nullptr;
    case Builtin::Min:
    case Builtin::Max: {
      if (args.size() == 1 && is(args[0], Type::Kind::List)) return promoted(args[0]->element);
      TypePtr t = scalar(Type::Kind::Int);
      for (const TypePtr& a : args) {
        if (!numeric(a)) return nullptr;
        t = join(t, a);
      }
      return args.empty() ? nullptr : t;
    }
    case Builtin::Vec3:
      return scalar(Type::Kind::Vec3);
    case Builtin::MinBy:
    case Builtin::MaxBy:
    case Builtin::None:
      break;
  }
  return nullptr;
}

void Typer::stmt(BodyStmt& s) {
  using Kind = BodyStmt::Kind;
  switch (s.kind) {
    case Kind::Let:
      locals_[s.name] = expr(s.expr);
      return;
    case Kind::Var:  // state a later assignment computes: a sized number's promoted type
      locals_[s.name] = promoted(expr(s.expr));
      return;
    case Kind::Assign:
    case Kind::Accept:
    case Kind::Emit:
      expr(s.expr);
      return;
    case Kind::If:
      expr(s.expr);
      nested(s.then_body);
      nested(s.else_body);
      return;
    case Kind::Every:
      nested(s.then_body);
      return;
    case Kind::Set:
    case Kind::Unset:
    case Kind::Throttle:
      return;
  }
}

TypePtr port_type(const App& app, const std::string& port) {
  const Port* p = app.find_port(port);
  return p ? p->type : nullptr;
}

}  // namespace

bool type_body(Body& body, const TypePtr& message) {
  Typer t(message);
  t.block(body);
  return t.ok();
}

bool type_expr(BodyExpr& e, const TypePtr& message) {
  Typer t(message);
  t.expr(e);
  return t.ok();
}

void type_bodies(App& app) {
  for (Connection& c : app.connections)
    if (c.body) type_body(*c.body, port_type(app, c.source));
  for (ArbitratedPort& p : app.arbitrated_ports)
    for (Assertion& a : p.asserts)
      if (a.emitted) type_expr(*a.emitted, port_type(app, p.port));
  for (Resource& r : app.resources)
    if (r.uses && !r.ports.empty()) type_expr(*r.uses, port_type(app, r.ports.front()));
}

}  // namespace arbc::model
