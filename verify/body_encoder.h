// The body encoder's class, shared by its two files: body_encoding.cc (expressions, statements)
// and builtin_calls.cc (calls of builtins). Internal to verify/: encode_body (body_encoding.h)
// is the interface.
#pragma once

#include <z3++.h>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/body.h"
#include "verify/body_encoding.h"
#include "verify/lua_number.h"
#include "verify/sym_value.h"

namespace arbc::verify::body {

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

// An int as a float (BodyExpr::Op::ToFloat, Lua's conversion); an unread operand stays unread.
inline Ev to_float(const Ev& a) {
  return a.unread || a.v.kind != K::Int ? a : Ev{{K::Float, lua::to_float(a.v)}, a.ok};
}

class Encoder {
 public:
  Encoder(z3::context& ctx, const SymValue& msg, std::string prefix, EncodedBody& out,
          bool abstract_lengths, std::string clock)
      : ctx_(ctx),
        msg_(msg),
        prefix_(std::move(prefix)),
        out_(out),
        abstract_lengths_(abstract_lengths),
        clock_(std::move(clock)) {}

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
  Ev compare(const std::string& op, const Ev& a, const Ev& b, bool unsigned_order);
  Ev call(const BodyExpr& e);
  Ev best_by(const BodyExpr& e, bool min);
  Ev min_max(const BodyExpr& e, bool min);
  Ev index(const Ev& list, const Ev& i);
  std::vector<std::pair<const SymValue*, z3::expr>> scanned(const SymValue& list);
  Ev vec_op(const std::string& op, const Ev& a, const Ev& b);
  Ev length(bool dist, const std::vector<Ev>& args, const z3::expr& ok);
  // A reading of the run's clock the proof does not know (now(), age()): finite, and not
  // negative unless `signed_`; abstracted, and named `text` in the state of a counterexample.
  SymValue clock_value(const std::string& what, const std::string& text, bool signed_);
  // age(t) as the prelude computes it: stamp_now() - (t.sec + t.nanosec * 1e-9).
  Ev age(const Ev& stamp);

  void exec(const std::vector<BodyStmt>& block, z3::expr& alive, SymValue& emitted);
  void exec_if(const BodyStmt& s, z3::expr& alive, SymValue& emitted);
  void exec_var(const BodyStmt& s, z3::expr& alive);

  z3::context& ctx_;
  const SymValue& msg_;
  std::string prefix_;
  EncodedBody& out_;
  bool abstract_lengths_;
  std::string clock_;  // encode_body's: the name of the clock age() reads, or "" (its own)
  std::map<std::string, SymValue> locals_;
  std::map<std::string, SymValue> params_;
  int counter_ = 0;
};

}  // namespace arbc::verify::body
