#include "verify/body_encoding.h"

#include <cmath>
#include <map>

namespace arbc::verify {

namespace {

using model::BodyExpr;
using model::BodyStmt;
using K = SymValue::Kind;

// A value and the condition under which computing it raises nothing (the generated Lua
// drops the message `no-value` otherwise).
struct Ev {
  SymValue v;
  z3::expr ok;
  // bad(): the value could not be encoded and `v` is a Bool placeholder. Every expression
  // over it is unread too, without touching Z3: the placeholder's sort and shape are not the
  // operand's, and Z3 crashes on mismatched sorts (tests/drt: Real * Bool, a norm of a Bool).
  bool unread = false;
};

// A numeral that is not zero: the only divisors `/` and `%` encode.
bool nonzero_numeral(const z3::expr& e) {
  z3::expr s = e.simplify();
  if (!s.is_numeral()) return false;
  z3::expr zero = s.is_int() ? s.ctx().int_val(0) : s.ctx().real_val(0);
  return (s != zero).simplify().is_true();
}

// An int as a float (BodyExpr::Op::ToFloat); an unread operand stays unread.
Ev to_float(const Ev& a) { return a.unread ? a : Ev{{K::Real, as_real(a.v)}, a.ok}; }

class Encoder {
 public:
  Encoder(z3::context& ctx, const SymValue& msg, std::string prefix, EncodedBody& out)
      : ctx_(ctx), msg_(msg), prefix_(std::move(prefix)), out_(out) {}

  void run(const model::Body& body) {
    z3::expr alive = ctx_.bool_val(true);
    SymValue emitted = msg_;  // without `emit`, the input unchanged
    exec(body, alive, emitted);
    if (!out_.opaque.empty()) return;
    out_.accepts = alive;
    out_.emitted = emitted;
  }

 private:
  void opaque(const std::string& why) {
    if (out_.opaque.empty()) out_.opaque = why;
  }
  Ev bad(const std::string& why) {
    opaque(why);
    return {SymValue(ctx_), ctx_.bool_val(false), true};
  }
  // An expression over an unread operand: the reason is given already.
  Ev unread() { return {SymValue(ctx_), ctx_.bool_val(false), true}; }
  std::string fresh_name(const std::string& what) {
    return prefix_ + "." + what + "#" + std::to_string(counter_++);
  }

  Ev eval(const BodyExpr& e);
  Ev binary(const BodyExpr& e);
  Ev record(const BodyExpr& e);
  Ev list(const BodyExpr& e);
  Ev arith(const std::string& op, const Ev& a, const Ev& b);
  Ev compare(const std::string& op, const Ev& a, const Ev& b);
  Ev call(const BodyExpr& e);
  Ev best_by(const BodyExpr& e, bool min);
  Ev min_max(const BodyExpr& e, bool min);
  Ev index(const Ev& list, const Ev& i);
  Ev vec_op(const std::string& op, const Ev& a, const Ev& b);
  SymValue sqrt_of(const z3::expr& square);
  Ev mod(const SymValue& a, const SymValue& b);

  void exec(const std::vector<BodyStmt>& block, z3::expr& alive, SymValue& emitted);
  void exec_if(const BodyStmt& s, z3::expr& alive, SymValue& emitted);
  void exec_var(const BodyStmt& s, z3::expr& alive);

  z3::context& ctx_;
  const SymValue& msg_;
  std::string prefix_;
  EncodedBody& out_;
  std::map<std::string, SymValue> locals_;
  std::map<std::string, SymValue> params_;
  int counter_ = 0;
};

Ev Encoder::eval(const BodyExpr& e) {
  switch (e.op) {
    case BodyExpr::Op::Message:
      return {msg_, ctx_.bool_val(true)};
    case BodyExpr::Op::Int:
      return {{K::Int, ctx_.int_val(e.integer)}, ctx_.bool_val(true)};
    case BodyExpr::Op::Float: {
      if (!std::isfinite(e.number)) return bad("a constant that is not a finite number");
      return {{K::Real, exact_real(ctx_, e.number)}, ctx_.bool_val(true)};
    }
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
      return {{a.v.kind, -a.v.scalar}, a.ok};
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
  SymValue l(K::List, ctx_.int_val(static_cast<int>(e.args.size())));
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
    return {{K::Bool, op == "==" ? *eq : !*eq}, a.ok && b.ok};
  }
  if (op == "<" || op == "<=" || op == ">" || op == ">=") return compare(op, a, b);
  if (a.v.kind == K::Vec3 || b.v.kind == K::Vec3) return vec_op(op, a, b);
  if (op == "+" && a.v.kind == K::String)
    return {{K::String, z3::concat(a.v.scalar, b.v.scalar)}, a.ok && b.ok};
  if (op == "+" && a.v.kind == K::List) {
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

Ev Encoder::compare(const std::string& op, const Ev& a, const Ev& b) {
  if (!a.v.numeric() || !b.v.numeric())
    return bad("`" + op + "` on strings (byte order is not encoded)");
  bool ints = a.v.kind == K::Int && b.v.kind == K::Int;
  z3::expr x = ints ? a.v.scalar : as_real(a.v);
  z3::expr y = ints ? b.v.scalar : as_real(b.v);
  z3::expr r = op == "<" ? x < y : op == "<=" ? x <= y : op == ">" ? x > y : x >= y;
  return {{K::Bool, r}, a.ok && b.ok};
}

Ev Encoder::arith(const std::string& op, const Ev& a, const Ev& b) {
  if (!a.v.numeric() || !b.v.numeric()) return bad("`" + op + "` on values that are not numbers");
  z3::expr ok = a.ok && b.ok;
  if (op == "/") {
    if (!nonzero_numeral(b.v.scalar)) return bad("`/` by a value that is not a nonzero constant");
    return {{K::Real, as_real(a.v) / as_real(b.v)}, ok};
  }
  if (op == "%") {
    if (!nonzero_numeral(b.v.scalar)) return bad("`%` by a value that is not a nonzero constant");
    Ev m = mod(a.v, b.v);
    return {m.v, ok};
  }
  bool ints = a.v.kind == K::Int && b.v.kind == K::Int;
  z3::expr x = ints ? a.v.scalar : as_real(a.v);
  z3::expr y = ints ? b.v.scalar : as_real(b.v);
  z3::expr r = op == "+" ? x + y : op == "-" ? x - y : x * y;
  if (op != "+" && op != "-" && op != "*") return bad("the operator `" + op + "`");
  return {{ints ? K::Int : K::Real, r}, ok};
}

// math.fmod(a, b) with b a nonzero constant: a - b * trunc(a / b), the sign of a.
Ev Encoder::mod(const SymValue& a, const SymValue& b) {
  if (a.kind == K::Int && b.kind == K::Int) {
    z3::expr babs = z3::ite(b.scalar < 0, -b.scalar, b.scalar);
    z3::expr qabs = z3::ite(a.scalar >= 0, a.scalar / babs, -((-a.scalar) / babs));
    z3::expr q = z3::ite(b.scalar < 0, -qabs, qabs);
    return {{K::Int, a.scalar - b.scalar * q}, ctx_.bool_val(true)};
  }
  z3::expr x = as_real(a), y = as_real(b);
  z3::expr ratio = x / y;
  // floor(r) as an Int (Z3's to_int; the C++ API of Z3 4.8 has no wrapper).
  auto floor_of = [&](const z3::expr& r) { return z3::expr(ctx_, Z3_mk_real2int(ctx_, r)); };
  z3::expr trunc =
      z3::ite(ratio >= 0, z3::to_real(floor_of(ratio)), -z3::to_real(floor_of(-ratio)));
  return {{K::Real, x - y * trunc}, ctx_.bool_val(true)};
}

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
      v.items.push_back({K::Real, -a.v.items[k].scalar});
    } else if ((op == "+" || op == "-") && a.v.kind == K::Vec3 && b.v.kind == K::Vec3) {
      const z3::expr &x = a.v.items[k].scalar, &y = b.v.items[k].scalar;
      v.items.push_back({K::Real, op == "+" ? x + y : x - y});
    } else if (op == "*" && (a.v.kind == K::Vec3) != (b.v.kind == K::Vec3)) {
      const SymValue& vec = a.v.kind == K::Vec3 ? a.v : b.v;
      const SymValue& num = a.v.kind == K::Vec3 ? b.v : a.v;
      v.items.push_back({K::Real, vec.items[k].scalar * as_real(num)});
    } else if (op == "/" && a.v.kind == K::Vec3 && b.v.numeric()) {
      if (!nonzero_numeral(b.v.scalar)) return bad("`/` by a value that is not a nonzero constant");
      v.items.push_back({K::Real, a.v.items[k].scalar / as_real(b.v)});
    } else {
      return bad("`" + op + "` on vec3");
    }
  }
  return {v, ok};
}

// A fresh r with r >= 0 and r * r = square: the real square root (nonlinear).
SymValue Encoder::sqrt_of(const z3::expr& square) {
  z3::expr r = ctx_.real_const(fresh_name("sqrt").c_str());
  out_.side.push_back(r >= 0 && r * r == square);
  return {K::Real, r};
}

// Dispatch on the builtin's id (core/builtins.h): a builtin added to the table without a case
// here does not compile (-Wswitch), and verify's builtin_encoding_test encodes each one.
Ev Encoder::call(const BodyExpr& e) {
  const std::string& f = e.text;
  switch (e.builtin) {
    case Builtin::MinBy:
    case Builtin::MaxBy:
      return best_by(e, e.builtin == Builtin::MinBy);
    case Builtin::Now: {
      SymValue t(K::Real, ctx_.real_const(fresh_name("now").c_str()));
      out_.abstracted.push_back("now()");
      out_.state.emplace_back("now()", t);
      return {t, ctx_.bool_val(true)};
    }
    case Builtin::Min:
    case Builtin::Max:
      return min_max(e, e.builtin == Builtin::Min);
    case Builtin::None:
      return bad("the call " + f + "()");
    case Builtin::Len:
    case Builtin::Abs:
    case Builtin::Vec3:
    case Builtin::Norm:
    case Builtin::Dist:
      break;  // of their evaluated arguments, below
  }
  std::vector<Ev> args;
  z3::expr ok = ctx_.bool_val(true);
  for (const BodyExpr& a : e.args) {
    args.push_back(eval(a));
    if (args.back().unread) return unread();
    ok = ok && args.back().ok;
  }
  if (e.builtin == Builtin::Len) {
    if (args.size() != 1 || args[0].v.kind != K::List)
      return bad("len of a string (byte length is not encoded)");
    return {{K::Int, args[0].v.scalar}, ok};
  }
  if (e.builtin == Builtin::Abs && args.size() == 1 && args[0].v.numeric()) {
    const z3::expr& x = args[0].v.scalar;
    return {{args[0].v.kind, z3::ite(x < 0, -x, x)}, ok};
  }
  if (e.builtin == Builtin::Vec3 && args.size() == 3) {
    SymValue v(K::Vec3, ctx_.bool_val(true));
    for (const Ev& a : args) v.items.push_back({K::Real, as_real(a.v)});
    return {v, ok};
  }
  bool dist = e.builtin == Builtin::Dist;
  if ((e.builtin == Builtin::Norm && args.size() == 1) || (dist && args.size() == 2)) {
    for (const Ev& a : args)
      if (a.v.kind != K::Vec3) return bad(f + " of a value that is not a vec3");
    z3::expr square = ctx_.real_val(0);
    for (size_t k = 0; k < 3; ++k) {
      z3::expr d = args[0].v.items[k].scalar;
      if (dist) d = d - args[1].v.items[k].scalar;
      square = square + d * d;
    }
    return {sqrt_of(square), ok};
  }
  return bad("the call " + f + "()");
}

// min_by / max_by: the first element with the smallest / largest key; none of an empty list.
Ev Encoder::best_by(const BodyExpr& e, bool min) {
  if (e.args.size() != 2 || e.args[1].op != BodyExpr::Op::Lambda)
    return bad(e.text + " without a lambda");
  Ev list = eval(e.args[0]);
  if (list.unread) return unread();
  if (list.v.kind != K::List || list.v.items.empty()) return bad(e.text + " of an empty literal");
  const BodyExpr& lambda = e.args[1];
  z3::expr ok = list.ok && list.v.scalar > 0;
  std::optional<SymValue> best;
  std::optional<z3::expr> best_key;
  for (size_t k = 0; k < list.v.items.size(); ++k) {
    std::optional<SymValue> saved;
    if (auto it = params_.find(lambda.text); it != params_.end()) saved = it->second;
    params_.insert_or_assign(lambda.text, list.v.items[k]);
    Ev key = eval(lambda.args[0]);
    if (key.unread) return unread();
    if (saved)
      params_.insert_or_assign(lambda.text, *saved);
    else
      params_.erase(lambda.text);
    if (!key.v.numeric()) return bad(e.text + " with a key that is not a number");
    z3::expr in = list.v.scalar > static_cast<int>(k);
    ok = ok && z3::implies(in, key.ok);
    z3::expr kv = as_real(key.v);
    if (!best) {
      best = list.v.items[k];
      best_key = kv;
      continue;
    }
    z3::expr better = in && (min ? kv < *best_key : kv > *best_key);
    best = merge(better, list.v.items[k], *best);
    if (!best) return bad("a list whose elements differ in shape");
    best_key = z3::ite(better, kv, *best_key);
  }
  return {*best, ok};
}

// min / max of numbers, or of one list (none of an empty list).
Ev Encoder::min_max(const BodyExpr& e, bool min) {
  std::vector<SymValue> xs;
  z3::expr ok = ctx_.bool_val(true);
  std::optional<z3::expr> len;
  for (const BodyExpr& a : e.args) {
    Ev x = eval(a);
    if (x.unread) return unread();
    ok = ok && x.ok;
    if (x.v.kind == K::List && e.args.size() == 1) {
      len = x.v.scalar;
      xs = x.v.items;
    } else {
      xs.push_back(x.v);
    }
  }
  if (xs.empty()) return bad(e.text + " of an empty literal");
  bool ints = true;
  for (const SymValue& x : xs) {
    if (!x.numeric()) return bad(e.text + " of values that are not numbers");
    ints = ints && x.kind == K::Int;
  }
  if (len) ok = ok && *len > 0;
  z3::expr best = ints ? xs[0].scalar : as_real(xs[0]);
  for (size_t k = 1; k < xs.size(); ++k) {
    z3::expr x = ints ? xs[k].scalar : as_real(xs[k]);
    z3::expr better = min ? x < best : x > best;
    if (len) better = better && *len > static_cast<int>(k);
    best = z3::ite(better, x, best);
  }
  return {{ints ? K::Int : K::Real, best}, ok};
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

}  // namespace

EncodedBody encode_body(z3::context& ctx, const model::Body& body, const SymValue& msg,
                        const std::string& prefix) {
  EncodedBody out(ctx);
  try {
    Encoder(ctx, msg, prefix, out).run(body);
  } catch (const z3::exception& e) {
    out.opaque = std::string("the solver rejected the encoding: ") + e.msg();
  }
  return out;
}

}  // namespace arbc::verify
