#include "verify/body_encoding.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "verify/body_encoder.h"
#include "verify/lua_number.h"

// The body encoder (body_encoder.h): expressions and statements; calls of builtins are in
// builtin_calls.cc.
namespace arbc::verify {

namespace body {

Ev Encoder::eval(const BodyExpr& e) {
  switch (e.op) {
    case BodyExpr::Op::Message:
      return {msg_, ctx_.bool_val(true)};
    case BodyExpr::Op::Int:
      return {{K::Int, lua::int_val(ctx_, e.integer)}, ctx_.bool_val(true)};
    case BodyExpr::Op::Float:
      return {{K::Float, lua::float_val(ctx_, e.number)}, ctx_.bool_val(true)};
    case BodyExpr::Op::String:
      return {{K::String, byte_string(ctx_, e.text)}, ctx_.bool_val(true)};
    case BodyExpr::Op::Bool:
      return {{K::Bool, ctx_.bool_val(e.boolean)}, ctx_.bool_val(true)};
    case BodyExpr::Op::Local:
    case BodyExpr::Op::Param: {
      auto& scope = e.op == BodyExpr::Op::Local ? locals_ : params_;
      auto it = scope.find(e.text);
      if (it == scope.end()) return bad("the name '" + e.text + "' is not defined");
      return {it->second, ctx_.bool_val(true)};
    }
    case BodyExpr::Op::Field: {
      Ev base = eval(e.args[0]);
      if (base.unread) return unread();
      if (base.v.kind == K::Vec3) {
        int k = e.text == "x" ? 0 : e.text == "y" ? 1 : e.text == "z" ? 2 : -1;
        if (k < 0) return bad("vec3 has no field '" + e.text + "'");
        return {base.v.items[static_cast<size_t>(k)], base.ok};
      }
      const SymValue* f = base.v.field(e.text);
      if (!f) return bad("no field '" + e.text + "'");
      return {*f, base.ok};
    }
    case BodyExpr::Op::Index: {
      Ev list = eval(e.args[0]), i = eval(e.args[1]);
      if (list.unread || i.unread) return unread();
      return index(list, i);
    }
    case BodyExpr::Op::Neg: {
      Ev a = eval(e.args[0]);
      if (a.unread) return unread();
      if (a.v.kind == K::Vec3) return vec_op("neg", a, a);
      if (!a.v.numeric()) return bad("`-` of a value that is not a number");
      return {lua::negate(a.v), a.ok};
    }
    case BodyExpr::Op::Not: {
      Ev a = eval(e.args[0]);
      if (a.unread) return unread();
      return {{K::Bool, !a.v.scalar}, a.ok};
    }
    case BodyExpr::Op::Binary:
      return binary(e);
    case BodyExpr::Op::Record:
      return record(e);
    case BodyExpr::Op::List:
      return list(e);
    case BodyExpr::Op::Lambda:
      return bad("a lambda outside min_by / max_by");
    case BodyExpr::Op::Call:
      return call(e);
    case BodyExpr::Op::ToFloat:
      return to_float(eval(e.args[0]));
  }
  return bad("an unknown expression");
}

// A record literal: its fields, valid when every field is.
Ev Encoder::record(const BodyExpr& e) {
  std::map<std::string, Ev> fields;
  z3::expr ok = ctx_.bool_val(true);
  for (size_t i = 0; i < e.args.size(); ++i) {
    Ev f = eval(e.args[i]);
    if (f.unread) return unread();
    ok = ok && f.ok;
    fields.emplace(e.names[i], f);
  }
  SymValue r(K::Record, ctx_.bool_val(true));
  for (auto& [name, f] : fields) {
    r.names.push_back(name);
    r.items.push_back(f.v);
  }
  return {r, ok};
}

// A list literal of known length: its elements, valid when every element is.
Ev Encoder::list(const BodyExpr& e) {
  SymValue l(K::List, lua::int_val(ctx_, static_cast<int64_t>(e.args.size())));
  z3::expr ok = ctx_.bool_val(true);
  for (const BodyExpr& a : e.args) {
    Ev x = eval(a);
    if (x.unread) return unread();
    ok = ok && x.ok;
    l.items.push_back(x.v);
  }
  return {l, ok};
}

Ev Encoder::index(const Ev& list, const Ev& i) {
  if (list.v.kind != K::List || i.v.kind != K::Int) return bad("an index that is not list[int]");
  if (list.v.items.empty()) return bad("an index into an empty list literal");
  const z3::expr& n = i.v.scalar;
  z3::expr ok = list.ok && i.ok && n >= 0 && n < list.v.scalar;
  // A constant index below the capacity reads an encoded element whatever the length; any other
  // index of a list of unknown length may reach past the capacity.
  z3::expr at = n.simplify();
  bool known = at.is_numeral() && lua::int_of(at) < static_cast<int64_t>(exact_prefix(list.v));
  if (!known && open_list(list.v)) out_.bounded = true;
  SymValue v = list.v.items.back();
  for (size_t k = list.v.items.size() - 1; k-- > 0;) {
    std::optional<SymValue> m = merge(n == static_cast<int>(k), list.v.items[k], v);
    if (!m) return bad("a list whose elements differ in shape");
    v = std::move(*m);
  }
  return {v, ok};
}

Ev Encoder::binary(const BodyExpr& e) {
  const std::string& op = e.text;
  Ev a = eval(e.args[0]);
  if (op == "and" || op == "or") {
    // Lua evaluates the right side only when the left does not decide.
    Ev b = eval(e.args[1]);
    if (a.unread || b.unread) return unread();
    bool is_and = op == "and";
    z3::expr value = is_and ? (a.v.scalar && b.v.scalar) : (a.v.scalar || b.v.scalar);
    z3::expr ok = a.ok && (is_and ? z3::implies(a.v.scalar, b.ok) : (a.v.scalar || b.ok));
    return {{K::Bool, value}, ok};
  }
  Ev b = eval(e.args[1]);
  if (a.unread || b.unread) return unread();
  if (op == "==" || op == "!=") {
    std::optional<z3::expr> eq = sym_equal(a.v, b.v);
    if (!eq) return bad("`" + op + "` of values of different shapes");
    if (open_list(a.v) || open_list(b.v)) out_.bounded = true;  // compares every element
    return {{K::Bool, op == "==" ? *eq : !*eq}, a.ok && b.ok};
  }
  if (op == "<" || op == "<=" || op == ">" || op == ">=") {
    bool unsigned_order = (e.args[0].type && is_uint64(*e.args[0].type)) ||
                          (e.args[1].type && is_uint64(*e.args[1].type));
    return compare(op, a, b, unsigned_order);
  }
  if (a.v.kind == K::Vec3 || b.v.kind == K::Vec3) return vec_op(op, a, b);
  if (op == "+" && a.v.kind == K::String)
    return {{K::String, z3::concat(a.v.scalar, b.v.scalar)}, a.ok && b.ok};
  if (op == "+" && a.v.kind == K::List) {
    if (open_list(a.v) || open_list(b.v)) out_.bounded = true;  // b's elements move
    SymValue l(K::List, a.v.scalar + b.v.scalar);
    // Element k of the result: a's when k < len(a), else b's element k - len(a).
    for (size_t k = 0; k < a.v.items.size() + b.v.items.size(); ++k) {
      std::optional<SymValue> v;
      for (size_t j = 0; j <= k && j < b.v.items.size(); ++j) {
        if (k - j > a.v.items.size()) continue;  // len(a) = k - j is impossible
        z3::expr at = a.v.scalar == static_cast<int>(k - j);
        v = v ? merge(at, b.v.items[j], *v) : b.v.items[j];
        if (!v) return bad("lists whose elements differ in shape");
      }
      if (k < a.v.items.size()) {
        z3::expr in_a = a.v.scalar > static_cast<int>(k);
        v = v ? merge(in_a, a.v.items[k], *v) : a.v.items[k];
        if (!v) return bad("lists whose elements differ in shape");
      }
      if (v) l.items.push_back(std::move(*v));
    }
    return {l, a.ok && b.ok};
  }
  return arith(op, a, b);
}

Ev Encoder::compare(const std::string& op, const Ev& a, const Ev& b, bool unsigned_order) {
  if (!a.v.numeric() || !b.v.numeric())
    return bad("`" + op + "` on strings (byte order is not encoded)");
  if (unsigned_order && a.v.kind == K::Int && b.v.kind == K::Int) {
    // A uint64's bits against an unsigned partner's (sema_numbers.cc): the monitor's math.ult.
    z3::expr r = op == "<"    ? z3::ult(a.v.scalar, b.v.scalar)
                 : op == "<=" ? z3::ule(a.v.scalar, b.v.scalar)
                 : op == ">"  ? z3::ult(b.v.scalar, a.v.scalar)
                              : z3::ule(b.v.scalar, a.v.scalar);
    return {{K::Bool, r}, a.ok && b.ok};
  }
  // Lua evaluates a > b as b < a and a >= b as b <= a.
  z3::expr r = op == "<"    ? lua::less(a.v, b.v)
               : op == "<=" ? lua::less_equal(a.v, b.v)
               : op == ">"  ? lua::less(b.v, a.v)
                            : lua::less_equal(b.v, a.v);
  return {{K::Bool, r}, a.ok && b.ok};
}

Ev Encoder::arith(const std::string& op, const Ev& a, const Ev& b) {
  if (!a.v.numeric() || !b.v.numeric()) return bad("`" + op + "` on values that are not numbers");
  z3::expr ok = a.ok && b.ok;
  if (op == "/") return {lua::divide(a.v, b.v), ok};
  if (op == "%") {
    // The generated Lua's arbc_fmod has no value for an int divided by int 0 (math.fmod
    // would raise): the monitor drops the message (no-value), so the value does not exist.
    z3::expr raises = ctx_.bool_val(false);
    SymValue m = lua::fmod(a.v, b.v, &raises);
    if (m.kind == K::Float) {
      m.scalar = m.scalar.simplify();
      if (!lua::is_float_numeral(m.scalar))
        return bad(
            "`%` on floats of the message (C's fmod of doubles is exact, but too large "
            "for the solver)");
    }
    return {m, ok && !raises};
  }
  if (op != "+" && op != "-" && op != "*") return bad("the operator `" + op + "`");
  return {lua::arith(op[0], a.v, b.v), ok};
}

// The arbc_v* helpers of the Lua prelude, component by component.
Ev Encoder::vec_op(const std::string& op, const Ev& a, const Ev& b) {
  // The other side of a scaling must be a number: an operand the encoding could not read
  // (bad(): a Bool placeholder) would reach Z3 as Real * Bool, which crashes it.
  const Ev& other = a.v.kind == K::Vec3 ? b : a;
  if (op != "neg" && other.v.kind != K::Vec3 && !other.v.numeric())
    return bad("`" + op + "` of a vec3 and a value not encoded");
  SymValue v(K::Vec3, ctx_.bool_val(true));
  z3::expr ok = a.ok && b.ok;
  for (size_t k = 0; k < 3; ++k) {
    if (op == "neg") {
      v.items.push_back(lua::negate(a.v.items[k]));
    } else if ((op == "+" || op == "-") && a.v.kind == K::Vec3 && b.v.kind == K::Vec3) {
      v.items.push_back(lua::arith(op[0], a.v.items[k], b.v.items[k]));
    } else if (op == "*" && (a.v.kind == K::Vec3) != (b.v.kind == K::Vec3)) {
      const SymValue& vec = a.v.kind == K::Vec3 ? a.v : b.v;
      const SymValue& num = a.v.kind == K::Vec3 ? b.v : a.v;
      v.items.push_back(lua::arith('*', vec.items[k], num));  // arbc_vscale: a.x * b
    } else if (op == "/" && a.v.kind == K::Vec3 && b.v.numeric()) {
      v.items.push_back(lua::divide(a.v.items[k], b.v));
    } else {
      return bad("`" + op + "` on vec3");
    }
  }
  return {v, ok};
}

void Encoder::exec_var(const BodyStmt& s, z3::expr& alive) {
  Ev init = eval(s.expr);
  (void)alive;  // the initialiser runs on the first message only: its failure is not assumed
  std::vector<const SymValue*> todo{&init.v};
  while (!todo.empty()) {
    const SymValue* v = todo.back();
    todo.pop_back();
    if (v->kind == K::List) return opaque("the list-valued var '" + s.name + "'");
    for (const SymValue& i : v->items) todo.push_back(&i);
  }
  SymValue state = fresh_like(ctx_, init.v, prefix_ + ".var." + s.name);
  out_.abstracted.push_back("var " + s.name);
  out_.state.emplace_back("var " + s.name, state);
  locals_.insert_or_assign(s.name, state);
}

void Encoder::exec_if(const BodyStmt& s, z3::expr& alive, SymValue& emitted) {
  Ev c = eval(s.expr);
  alive = alive && c.ok;
  std::map<std::string, SymValue> before = locals_;
  z3::expr alive_then = alive, alive_else = alive;
  SymValue em_then = emitted, em_else = emitted;
  exec(s.then_body, alive_then, em_then);
  std::map<std::string, SymValue> after_then = locals_;
  locals_ = before;
  exec(s.else_body, alive_else, em_else);
  const z3::expr& cond = c.v.scalar;
  alive = z3::ite(cond, alive_then, alive_else);
  std::optional<SymValue> em = merge(cond, em_then, em_else);
  // Shapes differ only when one side keeps the input and the other emits another type, which
  // sema allows only if that side cannot deliver: the emitting side's value is the one.
  emitted = em ? *em : (s.then_body.empty() ? em_else : em_then);
  // Variables declared before the `if` (vars assigned in a branch) merge; the branches' own
  // lets go out of scope.
  for (auto& [name, v] : before) {
    std::optional<SymValue> m = merge(cond, after_then.at(name), locals_.at(name));
    if (!m) return opaque("the var '" + name + "' changes shape");
    locals_.insert_or_assign(name, *m);
  }
  for (auto it = locals_.begin(); it != locals_.end();)
    it = before.count(it->first) ? std::next(it) : locals_.erase(it);
}

void Encoder::exec(const std::vector<BodyStmt>& block, z3::expr& alive, SymValue& emitted) {
  for (const BodyStmt& s : block) {
    if (!out_.opaque.empty()) return;
    switch (s.kind) {
      case BodyStmt::Kind::Let: {
        Ev v = eval(s.expr);
        alive = alive && v.ok;
        locals_.insert_or_assign(s.name, v.v);
        break;
      }
      case BodyStmt::Kind::Var:
        exec_var(s, alive);
        break;
      case BodyStmt::Kind::Assign: {
        Ev v = eval(s.expr);
        alive = alive && v.ok;
        locals_.insert_or_assign(s.name, v.v);
        break;
      }
      case BodyStmt::Kind::Accept: {
        Ev v = eval(s.expr);
        z3::expr t = ctx_.bool_const(fresh_name("accept" + std::to_string(s.line)).c_str());
        out_.trackers.push_back({t, s.line});
        alive = alive && v.ok && z3::implies(t, v.v.scalar);
        break;
      }
      case BodyStmt::Kind::If:
        exec_if(s, alive, emitted);
        break;
      case BodyStmt::Kind::Emit: {
        Ev v = eval(s.expr);
        alive = alive && v.ok;
        emitted = v.v;
        break;
      }
      case BodyStmt::Kind::Set:
      case BodyStmt::Kind::Unset:
      case BodyStmt::Kind::Throttle:
      case BodyStmt::Kind::Every:
        break;  // events are the effective guard's; throttle only removes deliveries
    }
  }
}

}  // namespace body

EncodedBody encode_body(z3::context& ctx, const model::Body& body, const SymValue& msg,
                        const std::string& prefix, bool abstract_lengths,
                        const std::string& clock) {
  EncodedBody out(ctx);
  try {
    body::Encoder(ctx, msg, prefix, out, abstract_lengths, clock).run(body);
  } catch (const z3::exception& e) {
    out.opaque = std::string("the solver rejected the encoding: ") + e.msg();
  }
  return out;
}

}  // namespace arbc::verify
