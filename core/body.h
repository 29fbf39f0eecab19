// A rule's monitor body in the core model (docs/app-json.md#bodies): the one translation of a
// body that both the verifier encodes (docs/design.md#the-proof) and the Lua generators write
// (docs/lowering.md#the-generated-lua). Lowering writes it from the checked AST with names
// resolved, constants folded and every int-to-float promotion explicit (`ToFloat`); app.json
// stores it as text (body_text.h), so `arbc verify app.json` proves what `arbc verify SPEC`
// proves without the compiler.
//
// Static types are not in the text: core/body_types.h derives them from the message's type, the
// one function both lowering and the app.json reader call, so a body has the same types
// whichever way it was made (an `int` literal is Int, a `float` literal Float).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/builtins.h"
#include "core/instant.h"
#include "core/type.h"

namespace arbc::model {

// BodyExpr::text of an Op::Int that is a uint64 above 2^63 - 1.
inline constexpr const char* kUint64Literal = "uint64";

struct BodyExpr {
  enum class Op {
    Message,  // the incoming message
    Int,      // integer holds an int literal (a folded int constant), exactly; text "uint64"
              // for a uint64 literal above 2^63 - 1, whose bits integer holds
    Float,    // number holds a float literal (a folded float or duration constant)
    String,   // text
    Bool,     // boolean
    Local,    // text: a `let` or `var` of the body
    Param,    // text: the parameter of the enclosing lambda
    Field,    // args[0].text
    Index,    // args[0][args[1]], counting from 0
    Neg,      // -args[0]
    Not,      // not args[0]
    Binary,   // text is one of + - * / % < <= > >= == != and or; args[0], args[1]
    Record,   // { names[i]: args[i] }
    List,     // [ args... ]
    Lambda,   // text => args[0]
    Call,     // text(args...): builtin says which (core/builtins.h), text is its name
    ToFloat,  // args[0], an int, as a float: where the spec's type is float and the operand int
              // (docs/design.md#numbers-at-run-time)
  };
  Op op = Op::Bool;
  Builtin builtin = Builtin::None;  // Call; None: a name no builtin has (opaque to the proof)
  std::string text;
  double number = 0;    // Float
  int64_t integer = 0;  // Int
  bool boolean = false;
  std::vector<std::string> names;  // Record
  std::vector<BodyExpr> args;
  TypePtr type;  // the static type (core/body_types.h); null for a lambda or an ill-typed node
  // Int / Float / String / Bool that fold a named `const`: its name and where it is declared,
  // so that generated Lua can define it once and name it. Not in app.json; no proof reads it.
  std::string constant;
  int constant_line = 0, constant_column = 0;
};

struct BodyStmt {
  enum class Kind {
    Let,       // let name = expr
    Var,       // var name = expr  (monitor state, initialised once)
    Assign,    // name = expr      (name is a var)
    Accept,    // accept expr
    Set,       // set name         (an event; the verifier reads effects from the connection)
    Unset,     // unset name
    If,        // if expr { then_body } else { else_body }
    Emit,      // emit expr
    Throttle,  // throttle (the period is the connection's `throttle`)
    Every,     // every { then_body }  (the period is the connection's `trig_interval`)
  };
  Kind kind = Kind::Accept;
  int line = 0;  // spec line, 0 if unknown
  std::string name;
  BodyExpr expr;
  std::vector<BodyStmt> then_body, else_body;
  // Set: the lifetime `for D` gives; none: the event's declared lifetime, else until unset.
  // Not used by the proofs (they read effects from the connection); `arbc docs` names it.
  std::optional<Nanos> lifetime;
};

using Body = std::vector<BodyStmt>;

}  // namespace arbc::model
